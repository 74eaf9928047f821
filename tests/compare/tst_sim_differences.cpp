// The simulator's deliberate differences (sim/differences.h): their option texts parsed and
// refused in words, and what each does to a snapshot; the latency holds output back.
#include "builtin/simulators.h"
#include "sim/differences.h"
#include "sim/receiver.h"
#include "sim/sky_model.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;

class TstSimDifferences : public QObject {
    Q_OBJECT
private slots:
    void optionTextsAreParsedOrRefused_data() {
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::newRow("offset") << "offset"
                                << "0.3,-0.2,+0.5" << true;
        QTest::newRow("offset, two") << "offset"
                                     << "0.3,-0.2" << false;
        QTest::newRow("offset, words") << "offset"
                                       << "a,b,c" << false;
        QTest::newRow("cn0, all") << "cn0"
                                  << "-2.5" << true;
        QTest::newRow("cn0, per system") << "cn0"
                                         << "GPS:-3,glonass:2,E:1" << true;
        QTest::newRow("cn0, unknown system") << "cn0"
                                             << "XYZ:3" << false;
        QTest::newRow("cn0, no value") << "cn0"
                                       << "GPS:" << false;
        QTest::newRow("drop") << "drop"
                              << "G05,R12,E31,C07" << true;
        QTest::newRow("drop, no number") << "drop"
                                         << "G" << false;
        QTest::newRow("drop, unknown system") << "drop"
                                              << "X05" << false;
    }
    void optionTextsAreParsedOrRefused() {
        QFETCH(QString, option);
        QFETCH(QString, text);
        QFETCH(bool, ok);
        std::string error;
        const std::string t = text.toStdString();
        const auto d = option == "offset" ? parseOffset(t, {}, error)
                       : option == "cn0"  ? parseCn0Offset(t, {}, error)
                                          : parseDrop(t, {}, error);
        QCOMPARE(d.has_value(), ok);
        QCOMPARE(error.empty(), ok);
        if (!ok) QVERIFY2(error.find(t) != std::string::npos, error.c_str());
    }

    void whatEachDoesToASnapshot() {
        std::string error;
        Differences d = *parseOffset("3,-4,5", {}, error);
        d = *parseCn0Offset("GPS:-3,GLONASS:50", d, error);
        d = *parseDrop("G05", d, error);
        SkySnapshot snap;
        snap.fix = FixKind::Autonomous;
        snap.lat = 55.75;
        snap.lon = 37.62;
        snap.altMsl = 150;
        snap.satellites = {{Constellation::Gps, 5, 0, 40, 100, 44, true, true},
                           {Constellation::Gps, 7, 0, 30, 200, 2, true, true},
                           {Constellation::Glonass, 1, 0, 20, 300, 30, true, false}};
        snap.used = 2;
        applyDifferences(d, snap);
        QCOMPARE(int(snap.satellites.size()), 2);
        QCOMPARE(snap.used, 1);
        QCOMPARE(snap.satellites[0].snr, 0.0); // 2 - 3: never below 0
        QCOMPARE(snap.satellites[1].snr, 80.0);
        QVERIFY(std::abs(snap.altMsl - 155) < 1e-6);
        QVERIFY(snap.lat < 55.75 && snap.lon > 37.62);
    }

    // A start between two whole seconds: epochs stay on UTC's whole seconds, and what a receiver
    // sends once a second (the GeoS-5's GSV, ZDA) still comes every second.
    void aStartOfItsOwnKeepsTheUtcGrid_data() {
        QTest::addColumn<QString>("dialect");
        for (const char *d : {"nvs", "geostar", "nemerix", "nmea"}) QTest::newRow(d) << d;
    }
    void aStartOfItsOwnKeepsTheUtcGrid() {
        QFETCH(QString, dialect);
        SimOptions o;
        o.startAfter = 3 * 3600 + 0.37; // 13:00:00.37
        auto rx = builtinSimulators().make(dialect.toStdString(), o);
        rx->advance(10.0);
        const std::string out = rx->takeOutput();
        QVERIFY(out.find("GGA,130001.00") != std::string::npos ||
                out.find("GGA,130001.000") != std::string::npos);
        QVERIFY2(out.find(".37") == std::string::npos || dialect == "nvs",
                 out.substr(0, 300).c_str());
        if (dialect == "geostar") {
            std::size_t gsv = 0;
            for (auto at = out.find("GSV,"); at != std::string::npos; at = out.find("GSV,", at + 1))
                ++gsv;
            QVERIFY2(gsv >= 9 * 9, qPrintable(QString::number(gsv)));
        }
    }

    void latencyHoldsOutputBack() {
        SimOptions now, later;
        later.differences.latency = 0.25;
        auto a = builtinSimulators().make("nmea", now), b = builtinSimulators().make("nmea", later);
        a->advance(1.0);
        b->advance(1.0);
        const std::string first = a->takeOutput();
        QVERIFY(!first.empty());
        // Epochs at 0 s and 1 s: the one of 1 s is not out yet.
        const std::string held = b->takeOutput();
        QVERIFY(held.size() < first.size());
        b->advance(0.25);
        QCOMPARE(held + b->takeOutput(), first + a->takeOutput());
    }
};

QTEST_GUILESS_MAIN(TstSimDifferences)
#include "tst_sim_differences.moc"
