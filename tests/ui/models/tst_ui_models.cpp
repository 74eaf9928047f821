// The Qt item models on their own: a receiver session fills the satellite, state, statistics and
// console models from decoded sentences. This suite links gnss_ui_models and no Qt Widgets: the
// models build without them (issue #13, build layers).
#include "models/console_model.h"
#include "session_feed.h"

#include <QGuiApplication>

#ifdef QT_WIDGETS_LIB
#error "gnss_ui_models must not bring in Qt Widgets"
#endif
#include <QTest>

using namespace gnss;

class TstUiModels : public QObject {
    Q_OBJECT
private slots:
    void aSessionFillsTheModelsWithoutWidgets() {
        test::SessionFixture f;
        f.feed({"GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,",
                "GPGSV,2,1,08,01,40,083,46,02,17,308,41,12,07,344,39,14,22,228,45",
                "GPGSV,2,2,08,15,30,050,44,18,42,110,43,20,55,210,47,24,12,290,38",
                "GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W",
                "GPGGA,123520,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"});
        QCOMPARE(f.satellites.rowCount(), 8);
        QVERIFY(f.state.state().epoch.lat.has_value());
        QCOMPARE(*f.state.state().epoch.lat, 48 + 7.038 / 60);
        QVERIFY(f.messages.rowCount() >= 3);
        QVERIFY(f.console.rowCount() >= 5);
    }

    // Lines that arrive faster than the view takes them (the event loop busy, a fast replay)
    // wait in a bounded buffer, whose room is given back after the burst: the soak's one-off
    // heap step of 3.5 to 7 MB was this buffer grown to 65 536 lines before the first flush.
    void aBurstBetweenFlushesIsBoundedAndItsRoomGivenBack() {
        ui::ConsoleModel console;
        const int burst = ui::ConsoleModel::kMaxLines * 5;
        for (int i = 0; i < burst; ++i) {
            ui::ConsoleLine l;
            l.text = "$GPGGA," + QByteArray::number(i);
            console.append(std::move(l));
            QVERIFY(console.pendingLines() <= std::size_t(ui::ConsoleModel::kMaxPending));
        }
        QVERIFY(console.pendingCapacity() <= 2 * std::size_t(ui::ConsoleModel::kMaxPending));
        console.flush();
        // What is shown is the newest kMaxLines, in order, as if every line had been kept.
        QCOMPARE(console.rowCount(), ui::ConsoleModel::kMaxLines);
        const int first = burst - ui::ConsoleModel::kMaxLines;
        QVERIFY(console.data(console.index(0))
                        .toString()
                        .endsWith("$GPGGA," + QString::number(first)));
        QVERIFY(console.data(console.index(console.rowCount() - 1))
                        .toString()
                        .endsWith("$GPGGA," + QString::number(burst - 1)));
        QCOMPARE(console.pendingLines(), std::size_t(0));
        // Lines still coming fast keep their room; the first ordinary flush after the burst (a
        // few hundred lines, as at 20 Hz) gives it back.
        QVERIFY(console.pendingCapacity() <= 2 * std::size_t(ui::ConsoleModel::kMaxPending));
        for (int i = 0; i < 300; ++i) console.append(ui::ConsoleLine{});
        console.flush();
        QVERIFY2(console.pendingCapacity() < 5000,
                 qPrintable(QString::number(console.pendingCapacity())));
        // And ordinary flushes keep their small room: nothing is reallocated each time.
        for (int i = 0; i < 300; ++i) console.append(ui::ConsoleLine{});
        const std::size_t room = console.pendingCapacity();
        console.flush();
        QCOMPARE(console.pendingCapacity(), room);
    }
};

// A QGuiApplication (the models use colours), not a QApplication: no Widgets.
QTEST_MAIN(TstUiModels)
#include "tst_ui_models.moc"
