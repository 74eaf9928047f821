// RtkView: RTK state decoded from NVS spec sentences shows in the panel's labels; missing values
// show "—"; the correction-age watchdog turns red past its threshold; refresh is timer-driven.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "label_text.h"
#include "models/receiver_state_model.h"
#include "screenshot.h"
#include "state/state_tracker.h"
#include "track_state.h"
#include "views/rtk_view.h"

#include <QLabel>
#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::ui;

namespace {

ReceiverState track(const std::vector<std::string> &lines) {
    return test::trackState(lines);
}

// The NV08C-RTK sentences of the NVS spec examples (and tst_state_tracker).
ReceiverState nvsRtkState() {
    return track({buildSentence("GPGGA,145505.20,4724.5118287,N,00937.6956032,E,4,17,0.7,403.995,"
                                "M,47.848,M,2.2,0002"),
                  buildSentence("PNVGBSS,1200,3,1197,4769.223,1.2"),
                  "$PNVGBRS,091244.60,4604.566,-1242.064,-27.096,4769.223,344.90,-0.33,R*1A",
                  "$PNVGBLS,145505.20,0.437,0.374,-0.040,0.576,40.61,-4.01,R*1A",
                  "$PNVGSDP,151337.40,0.005,0.004,0.009,R*38",
                  "$PNVGSDV,151337.40,0.087,0.077,0.118,R*31", "$PNVGSDH,151337.40,0.978,R*2E",
                  "$PNVGDOP,121707.80,1.06,0.94,0.59,0.73,0.50,0.41,0.42,R*14"});
}

QString text(const QWidget &w, const char *name) {
    return test::labelText(w, name);
}

QColor textColor(const QWidget &w, const char *name) {
    return w.findChild<QLabel *>(QString::fromLatin1(name))->palette().color(QPalette::WindowText);
}

} // namespace

class TstRtkView : public QObject {
    Q_OBJECT
private slots:
    void hiddenUntilTheReceiverReportsRtk() {
        ReceiverStateModel model;
        RtkView view(&model);
        QVERIFY(!view.rtkAvailable());
        QSignalSpy spy(&view, &RtkView::availabilityChanged);
        model.publish(nvsRtkState());
        view.refresh();
        QVERIFY(view.rtkAvailable());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toBool(), true);
    }

    void nvsSentencesShowInEveryGroup() {
        ReceiverStateModel model;
        RtkView view(&model);
        const ReceiverState st = nvsRtkState();
        QVERIFY(st.rtk.seen);
        model.publish(st);
        view.refresh();
        QCOMPARE(text(view, "rtkMode"), QString("RTK fixed"));
        QCOMPARE(text(view, "rtkRtcmTotal"), QString("1200"));
        QCOMPARE(text(view, "rtkRtcmErrors"), QString("3"));
        QCOMPARE(text(view, "rtkRtcmOk"), QString("1197"));
        QCOMPARE(text(view, "rtkBaseDistance"), QString("4769.223 m"));
        QCOMPARE(text(view, "rtkCorrectionAge"), QString("1.2 s"));
        QCOMPARE(text(view, "rtkBaselineNorth"), QString("4604.566 m"));
        QCOMPARE(text(view, "rtkBaselineEast"), QString("-1242.064 m"));
        QCOMPARE(text(view, "rtkBaselineVertical"), QString("-27.096 m"));
        QCOMPARE(text(view, "rtkBaselineLength"), QString("4769.223 m"));
        QCOMPARE(text(view, "rtkBaselineCourse"), QString("344.90°"));
        QCOMPARE(text(view, "rtkBaselinePitch"), QString("-0.33°"));
        QCOMPARE(text(view, "rtkHeading"), QString("40.61°"));
        QCOMPARE(text(view, "rtkAntennaPitch"), QString("-4.01°"));
        QCOMPARE(text(view, "rtkAntennaLength"), QString("0.576 m"));
        QCOMPARE(text(view, "rtkSdLat"), QString("0.005 m"));
        QCOMPARE(text(view, "rtkSdHeight"), QString("0.009 m"));
        QCOMPARE(text(view, "rtkSdVelUp"), QString("0.118 m/s"));
        QCOMPARE(text(view, "rtkSdHeading"), QString("0.978°"));
        QCOMPARE(text(view, "rtkGdop"), QString("1.06"));
        QCOMPARE(text(view, "rtkEdop"), QString("0.42"));
        QVERIFY(!view.correctionsLate());
    }

    void missingValuesShowADashNeverZero() {
        ReceiverStateModel model;
        RtkView view(&model);
        ReceiverState st;
        st.rtk.seen = true;
        st.rtk.mode = 'F';
        st.rtk.rtcmTotal = 0; // a real zero is shown as 0
        model.publish(st);
        view.refresh();
        const QString dash = QString(QChar(0x2014));
        QCOMPARE(text(view, "rtkMode"), QString("RTK float"));
        QCOMPARE(text(view, "rtkRtcmTotal"), QString("0"));
        for (const char *name :
             {"rtkRtcmErrors", "rtkBaseDistance", "rtkCorrectionAge", "rtkBaselineLength",
              "rtkHeading", "rtkSdLat", "rtkSdHeading", "rtkGdop", "rtkEdop", "rtkBaseId"})
            QCOMPARE(text(view, name), dash);
        QVERIFY(!view.correctionsLate());
    }

    void watchdogTurnsRedPastTheThreshold() {
        ReceiverStateModel model;
        RtkView view(&model);
        QCOMPARE(view.correctionAgeThreshold(), 10.0);
        const QColor normal = textColor(view, "rtkCorrectionAge");
        QVERIFY(normal != RtkView::alarmColor());

        ReceiverState st = nvsRtkState();
        st.rtk.correctionAge = 9.9;
        model.publish(st);
        view.refresh();
        QVERIFY(!view.correctionsLate());
        QCOMPARE(textColor(view, "rtkCorrectionAge"), normal);

        QSignalSpy spy(&view, &RtkView::correctionsLateChanged);
        st.rtk.correctionAge = 12.5;
        model.publish(st);
        view.refresh();
        QVERIFY(view.correctionsLate());
        QCOMPARE(textColor(view, "rtkCorrectionAge"), RtkView::alarmColor());
        QCOMPARE(textColor(view, "rtkWatchdog"), RtkView::alarmColor());
        QVERIFY(text(view, "rtkWatchdog").contains("12.5"));
        QCOMPARE(spy.count(), 1);

        // Raising the threshold clears the alarm at once, without a new epoch.
        view.setCorrectionAgeThreshold(15.0);
        QVERIFY(!view.correctionsLate());
        QCOMPARE(textColor(view, "rtkCorrectionAge"), normal);
        view.setCorrectionAgeThreshold(2.0);
        QVERIFY(view.correctionsLate());
    }

    void refreshesOnItsTimerNotPerUpdate() {
        ReceiverStateModel model;
        RtkView view(&model);
        model.publish(nvsRtkState());
        // Nothing is drawn from inside the model's signal...
        QCOMPARE(text(view, "rtkRtcmTotal"), QString(QChar(0x2014)));
        // ...the 10 Hz timer picks the epoch up.
        QTRY_COMPARE_WITH_TIMEOUT(text(view, "rtkRtcmTotal"), QString("1200"), 2000);
    }

    void screenshotReadsWell() {
        ReceiverStateModel model;
        RtkView view(&model);
        ReceiverState st = nvsRtkState();
        st.rtk.correctionAge = 14.2; // show the alarm
        model.publish(st);
        view.refresh();
        view.resize(900, 520);
        test::checkScreenshot(view, "rtk_view.png");
    }
};

QTEST_MAIN(TstRtkView)
#include "tst_rtk_view.moc"
