// Sky plot and signal levels: two views of one satellite model, fed from decoded sentences.
#include "session_feed.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"

#include <QTest>

using namespace gnss;

class TestSkyAndSignalViews : public QObject {
    Q_OBJECT
private slots:
    void skyPlotPlacesSatellitesByAzimuthAndElevation() {
        test::SessionFixture f;
        f.feed({"GPGGA,120000.00,5550.6129,N,03732.2527,E,1,03,0.9,180.0,M,14.4,M,,",
                "GPGSA,A,3,05,12,,,,,,,,,,,1.8,0.9,1.5",
                "GPGSV,1,1,03,05,90,000,45,12,00,090,38,14,45,180,", "GLGSV,1,1,01,70,30,270,41",
                "GPGGA,120001.00,5550.6129,N,03732.2527,E,1,03,0.9,180.0,M,14.4,M,,"});
        ui::SkyPlotView view(&f.satellites);
        view.resize(400, 400);
        const auto markers = view.markers();
        QCOMPARE(markers.size(), 4);
        const QPointF c(200, 200);
        for (const auto &m : markers) {
            if (m.label == "G05") { // zenith: the centre
                QVERIFY(QLineF(m.pos, c).length() < 1.0);
                QVERIFY(m.used);
                QCOMPARE(m.snr, 45);
            } else if (m.label == "G12") { // east, on the horizon
                QVERIFY(m.pos.x() > c.x() + 100 && std::abs(m.pos.y() - c.y()) < 1.0);
                QVERIFY(m.used);
            } else if (m.label == "G14") { // south, half way, no signal
                QVERIFY(m.pos.y() > c.y() + 40 && std::abs(m.pos.x() - c.x()) < 1.0);
                QCOMPARE(m.snr, -1);
                QVERIFY(!m.used);
            } else {
                QCOMPARE(m.label, QString("R06"));
                QVERIFY(m.pos.x() < c.x() - 50); // west
                QVERIFY(m.tooltip.contains("GLONASS"));
            }
        }
        view.setConstellationVisible(Constellation::Glonass, false);
        QCOMPARE(view.markers().size(), 3);
        const QImage img = view.grab().toImage();
        QVERIFY(!img.isNull());
    }

    void signalBarsAreGroupedByConstellationAndSignal() {
        test::SessionFixture f;
        f.feed({"GNGGA,120000.00,5550.6129,N,03732.2527,E,1,03,0.9,180.0,M,14.4,M,,",
                "GPGSV,1,1,02,05,40,083,46,07,20,100,40,1", "GPGSV,1,1,01,05,40,083,38,8",
                "GAGSV,1,1,01,11,50,200,44,7", "GNGSA,A,3,05,07,,,,,,,,,,,1.8,0.9,1.5,1",
                "GNGGA,120001.00,5550.6129,N,03732.2527,E,1,03,0.9,180.0,M,14.4,M,,"});
        QCOMPARE(f.satellites.rowCount(), 4);
        ui::SignalLevelsView view(&f.satellites);
        view.resize(600, 240);
        const auto bars = view.layoutBars();
        QCOMPARE(bars.size(), 4);
        QStringList labels;
        for (const auto &b : bars) labels << b.label;
        // GPS L1 (G05, G07), then GPS L5 (G05 L5-Q), then Galileo E1.
        QCOMPARE(labels, (QStringList{"G05", "G07", "G05 L5-Q", "E11 E1-BC"}));
        // Taller bar for the stronger signal; a gap between groups.
        QVERIFY(bars[0].rect.height() > bars[2].rect.height());
        QVERIFY(bars[2].rect.left() - bars[1].rect.right() >
                bars[1].rect.left() - bars[0].rect.right());
        QVERIFY(!view.grab().toImage().isNull());
    }

    void satellitesOutOfViewAreKeptThenDropped() {
        ui::SatelliteModel model;
        model.setKeepAfterLostMs(5000);
        Epoch e;
        e.satellites.push_back({{Constellation::Gps, 5}, 0, 40, 83, 46, true});
        model.update(e, 1000);
        QCOMPARE(model.rowCount(), 1);
        model.update(Epoch{}, 2000);
        QCOMPARE(model.rowCount(), 1);
        QCOMPARE(model.data(model.index(0, 0), ui::SatelliteModel::InViewRole).toBool(), false);
        model.update(Epoch{}, 7000);
        QCOMPARE(model.rowCount(), 0);
    }
};

QTEST_MAIN(TestSkyAndSignalViews)
#include "tst_sky_and_signal_views.moc"
