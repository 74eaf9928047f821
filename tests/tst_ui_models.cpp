// The Qt item models on their own: a receiver session fills the satellite, state, statistics and
// console models from decoded sentences. This suite links gnss_ui_models and no Qt Widgets: the
// models build without them (issue #13, build layers).
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
};

// A QGuiApplication (the models use colours), not a QApplication: no Widgets.
QTEST_MAIN(TstUiModels)
#include "tst_ui_models.moc"
