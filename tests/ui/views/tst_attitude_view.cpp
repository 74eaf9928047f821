// AttitudeView: roll/pitch/yaw and accelerations from the NVS IMU sentence; time-mark events in
// a table, newest first; "—" for what the receiver did not send.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "label_text.h"
#include "models/receiver_state_model.h"
#include "screenshot.h"
#include "state/state_tracker.h"
#include "track_state.h"
#include "views/attitude_view.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

using namespace gnss;
using namespace gnss::ui;

namespace {

ReceiverState track(const std::vector<std::string> &lines) {
    return test::trackState(lines);
}

QString text(const QWidget &w, const char *name) {
    return test::labelText(w, name);
}

TimeMarkEvent mark(std::int64_t counter, double tow) {
    TimeMarkEvent e;
    e.counter = counter;
    e.towSeconds = tow;
    return e;
}

} // namespace

class TstAttitudeView : public QObject {
    Q_OBJECT
private slots:
    void imuSentenceShowsAttitudeAndAcceleration() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        model.publish(track({"$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7C"}));
        view.refresh();
        QCOMPARE(text(view, "attitudeRoll"), QString("0.42°"));
        QCOMPARE(text(view, "attitudePitch"), QString("0.37°"));
        QCOMPARE(text(view, "attitudeYaw"), QString("21.84°"));
        QCOMPARE(text(view, "attitudeAccNorth"), QString("0.065 m/s²"));
        QCOMPARE(text(view, "attitudeAccEast"), QString("0.064 m/s²"));
        QCOMPARE(text(view, "attitudeAccDown"), QString("-0.201 m/s²"));
        QCOMPARE(text(view, "attitudeTime"), QString("14:55:05.200 UTC"));
    }

    void missingValuesShowADash() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        const QString dash(QChar(0x2014));
        for (const char *n : {"attitudeRoll", "attitudeYaw", "attitudeAccDown", "attitudeTime"})
            QCOMPARE(text(view, n), dash);
        QCOMPARE(view.findChild<QTableWidget *>("timeMarkTable")->rowCount(), 0);
    }

    void timeMarksFromNvsSentencesNewestFirst() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        model.publish(track({"$PNVGTME,128,40327.564756284*49", "$PNVGTMU,128,081248.547824228*61",
                             "$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,403.995,"
                             "M,47.848,M,2.2,0002*4D",
                             buildSentence("PNVGTME,129,40328.5")}));
        view.refresh();
        auto *table = view.findChild<QTableWidget *>("timeMarkTable");
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(0, AttitudeView::Counter)->text(), QString("129"));
        QCOMPARE(table->item(0, AttitudeView::Tow)->text(), QString("40328.500000"));
        QCOMPARE(table->item(0, AttitudeView::Latitude)->text(), QString(QChar(0x2014)));
        QCOMPARE(table->item(1, AttitudeView::Counter)->text(), QString("128"));
        QCOMPARE(table->item(1, AttitudeView::Tow)->text(), QString("40327.564756"));
        QCOMPARE(table->item(1, AttitudeView::Utc)->text(), QString("08:12:48.547824228"));
        QCOMPARE(table->item(1, AttitudeView::Latitude)->text(), QString("47.40853048° N"));
        QCOMPARE(table->item(1, AttitudeView::Longitude)->text(), QString("9.62826005° E"));
        QCOMPARE(table->item(1, AttitudeView::Altitude)->text(), QString("403.995"));
        QVERIFY(text(view, "timeMarkCount").contains("2"));
    }

    void aNewMarkGoesOnTopOnTheTimer() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        ReceiverState st;
        for (int i = 1; i <= 3; ++i) st.addTimeMark(mark(i, 100.0 + i));
        model.publish(st);
        auto *table = view.findChild<QTableWidget *>("timeMarkTable");
        QTRY_COMPARE_WITH_TIMEOUT(table->rowCount(), 3, 2000);
        QCOMPARE(table->item(0, 0)->text(), QString("3"));
        QCOMPARE(table->item(2, 0)->text(), QString("1"));
        // A full buffer: the count stays, the newest changes; the table must follow.
        st.timeMarks.pop_front();
        st.addTimeMark(mark(4, 104.0));
        model.publish(st);
        QTRY_COMPARE_WITH_TIMEOUT(table->item(0, 0)->text(), QString("4"), 2000);
        QCOMPARE(table->item(2, 0)->text(), QString("2"));
    }

    // The state keeps kMaxTimeMarks, the table the newest kMaxRows; after each rebuild (every
    // new mark of a full buffer rewrites every row) the columns fit their widest cell again.
    void aFullTableShowsTheNewestRowsWithColumnsFittingThem() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        view.show();
        ReceiverState st;
        for (std::size_t i = 1; i <= ReceiverState::kMaxTimeMarks + 5; ++i)
            st.addTimeMark(mark(std::int64_t(i), 1000.0 + double(i)));
        QCOMPARE(st.timeMarks.size(), ReceiverState::kMaxTimeMarks);
        model.publish(st);
        view.refresh();
        auto *table = view.findChild<QTableWidget *>("timeMarkTable");
        QCOMPARE(table->rowCount(), AttitudeView::kMaxRows);
        QCOMPARE(table->item(0, 0)->text(), QString::number(ReceiverState::kMaxTimeMarks + 5));
        st.addTimeMark(mark(123456789, 99999.123456)); // a wider counter and time of week
        model.publish(st);
        view.refresh();
        QCOMPARE(table->rowCount(), AttitudeView::kMaxRows);
        QCOMPARE(table->item(0, 0)->text(), QString("123456789"));
        QCOMPARE(table->horizontalHeader()->sectionResizeMode(0), QHeaderView::ResizeToContents);
        const QAbstractItemView *cells = table; // sizeHintForColumn is public here
        for (int c : {int(AttitudeView::Counter), int(AttitudeView::Tow)})
            QVERIFY2(table->columnWidth(c) >= cells->sizeHintForColumn(c),
                     qPrintable(QString("column %1: %2 < %3")
                                        .arg(c)
                                        .arg(table->columnWidth(c))
                                        .arg(cells->sizeHintForColumn(c))));
    }

    void screenshotReadsWell() {
        ReceiverStateModel model;
        AttitudeView view(&model);
        ReceiverState st =
                track({"$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7C",
                       "$PNVGTME,128,40327.564756284*49", "$PNVGTMU,128,081248.547824228*61",
                       "$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,"
                       "403.995,M,47.848,M,2.2,0002*4D"});
        for (int i = 129; i < 135; ++i) {
            TimeMarkEvent e = st.timeMarks.back();
            e.counter = i;
            *e.towSeconds += 1.0;
            st.addTimeMark(e);
        }
        model.publish(st);
        view.refresh();
        view.resize(820, 480);
        test::checkScreenshot(view, "attitude_view.png");
    }
};

QTEST_MAIN(TstAttitudeView)
#include "tst_attitude_view.moc"
