// Sky plot and signal levels: two views of one satellite model, fed from decoded sentences.
#include "session_feed.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"

#include <QTest>

using namespace gnss;

class TstSkyAndSignalViews : public QObject {
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

    void skyLabelsNeverOverlapEvenInCrowdsOfSixty_data() {
        QTest::addColumn<int>("size");
        for (int size : {160, 240, 320, 420, 700}) QTest::addRow("%dpx", size) << size;
    }
    void skyLabelsNeverOverlapEvenInCrowdsOfSixty() {
        // 60 satellites, a third of them in tight clusters of three (the spots where labels of
        // close satellites used to be drawn on top of each other).
        QFETCH(int, size);
        ui::SatelliteModel model;
        Epoch e;
        const Constellation systems[] = {Constellation::Gps, Constellation::Glonass,
                                         Constellation::Galileo, Constellation::BeiDou,
                                         Constellation::Sbas};
        for (int i = 0; i < 60; ++i) {
            const Constellation sys = systems[i % 5];
            const int prn = sys == Constellation::Sbas ? 120 + i / 5 : 1 + i / 5;
            const bool cluster = i < 21;
            const double el = cluster ? 30 + (i / 3) * 7 + (i % 3) * 0.5 : 5 + (i * 37) % 85;
            const double az = cluster ? (i / 3) * 50 + (i % 3) * 1.0 : (i * 71) % 360;
            e.satellites.push_back({{sys, prn}, 0, int(el), int(az), 30 + i % 20, i % 2 == 0});
        }
        model.update(e, 1000);
        ui::SkyPlotView view(&model);
        view.resize(size, size);
        const auto ms = view.markers();
        QCOMPARE(ms.size(), 60);
        const auto grid = view.gridTexts();
        QCOMPARE(grid.size(), 7);
        const double body = 8;
        int labelled = 0;
        for (int i = 0; i < ms.size(); ++i) {
            QVERIFY(!ms[i].tooltip.isEmpty()); // a dropped label still has its tooltip
            if (ms[i].labelRect.isNull()) {
                QVERIFY(ms[i].text.isEmpty());
                continue;
            }
            ++labelled;
            QVERIFY(view.rect().contains(ms[i].labelRect.toAlignedRect()));
            // Nor over a compass letter or a ring's degrees ("G26" over the W read "GW6").
            for (const auto &t : grid)
                QVERIFY2(!ms[i].labelRect.intersects(t.rect),
                         qPrintable(ms[i].text + " over " + t.text));
            for (int j = 0; j < ms.size(); ++j) {
                if (j == i) continue;
                QVERIFY2(!ms[j].labelRect.isNull() ? !ms[i].labelRect.intersects(ms[j].labelRect)
                                                   : true,
                         qPrintable(ms[i].text + " over " + ms[j].text));
                // Never over another satellite's marker either.
                const QRectF other(ms[j].pos - QPointF(body / 2, body / 2), QSizeF(body, body));
                QVERIFY2(!ms[i].labelRect.intersects(other),
                         qPrintable(ms[i].text + " hides " + ms[j].label));
            }
        }
        qInfo("%d px: %d of 60 labels placed", size, labelled);
        // Room decides how many: all of them in a big plot, most in a docked one.
        if (size >= 700) QCOMPARE(labelled, 60);
        if (size >= 420) QVERIFY2(labelled >= 45, qPrintable(QString::number(labelled)));
        QVERIFY(!view.grab().isNull());
    }

    void signalIdsStayLegibleAtAnyWidth_data() {
        QTest::addColumn<int>("width");
        for (int w : {160, 240, 320, 480, 640, 900, 1400, 2000}) QTest::addRow("%dpx", w) << w;
    }
    void signalIdsStayLegibleAtAnyWidth() {
        QFETCH(int, width);
        ui::SatelliteModel model;
        Epoch e;
        for (int i = 0; i < 60; ++i)
            e.satellites.push_back({{i < 30 ? Constellation::Gps : Constellation::Sbas,
                                     i < 30 ? i + 1 : 120 + i - 30},
                                    0,
                                    45,
                                    (i * 6) % 360,
                                    25 + i % 25,
                                    true});
        model.update(e, 1000);
        ui::SignalLevelsView view(&model);
        view.resize(width, 220);
        const auto lay = view.layout();
        QCOMPARE(lay.bars.size(), 60);
        int written = 0;
        for (int i = 0; i < lay.bars.size(); ++i) {
            if (lay.bars[i].id.isEmpty()) continue;
            ++written;
            QVERIFY(lay.bars[i].idRect.bottom() <= view.height());
            for (int j = i + 1; j < lay.bars.size(); ++j)
                if (!lay.bars[j].id.isEmpty())
                    QVERIFY2(!lay.bars[i].idRect.intersects(lay.bars[j].idRect),
                             qPrintable(lay.bars[i].id + " runs into " + lay.bars[j].id));
        }
        // Every id written while there is room for it; some, evenly spread, when there is not.
        if (width >= 900) QCOMPARE(written, 60);
        QVERIFY(written >= 60 / lay.every - 2);
        QVERIFY(!view.grab().isNull());
    }

    // A narrow group's caption is shortened, not cut: the full name, then the ids' letter with
    // the signal, then the signal alone, then the letter; elided only when nothing fits.
    void groupCaptionsShortenToFit_data() {
        QTest::addColumn<QString>("expected");
        QTest::newRow("room for all") << "GLONASS G2 C/A";
        QTest::newRow("letter and signal") << "R G2 C/A";
        QTest::newRow("signal alone") << "G2 C/A";
        QTest::newRow("letter alone") << "R";
    }
    void groupCaptionsShortenToFit() {
        QFETCH(QString, expected);
        const QFontMetricsF fm(QFont("DejaVu Sans", 9));
        const double width = fm.horizontalAdvance(expected);
        QCOMPARE(ui::SignalLevelsView::groupCaption(fm, Constellation::Glonass, 3, width),
                 expected);
        // Less room than the letter: the full name elided.
        const QString tiny = ui::SignalLevelsView::groupCaption(fm, Constellation::Glonass, 3,
                                                                fm.horizontalAdvance("R") - 1);
        QVERIFY(tiny.isEmpty() || tiny.endsWith(QChar(0x2026)));
        // No signal name: the constellation, then its letter.
        QCOMPARE(ui::SignalLevelsView::groupCaption(fm, Constellation::Gps, 0, 1000), "GPS");
        QCOMPARE(ui::SignalLevelsView::groupCaption(fm, Constellation::Gps, 0,
                                                    fm.horizontalAdvance("G")),
                 "G");
        // A satellite of no known system is named in words (translated), not "unknown".
        QCOMPARE(ui::SignalLevelsView::groupCaption(fm, Constellation::Unknown, 0, 1000),
                 "unknown system");
        ui::SatelliteModel model;
        Epoch e;
        e.satellites.push_back({{Constellation::Unknown, 101}, 0, 40, 83, 46, false});
        model.update(e, 1000);
        QCOMPARE(model.data(model.index(0, ui::SatelliteModel::System)).toString(),
                 QString("unknown system"));
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

QTEST_MAIN(TstSkyAndSignalViews)
#include "tst_sky_and_signal_views.moc"
