// The simulator's sky: plausible tracks, rise and set, SNR from elevation, elevation mask, DOPs
// from the used geometry, position noise by fix type, and determinism with a seed.
#include "sim/sky_model.h"

#include <QTest>

#include <cmath>
#include <map>

using namespace gnss;
using namespace gnss::sim;

class TstSimSky : public QObject {
    Q_OBJECT
private slots:
    void everyConstellationIsInView() {
        SkyModel sky(1);
        const auto snap = sky.update(0, UseMask{}, FixKind::Autonomous, -100);
        std::map<Constellation, int> count;
        for (const auto &s : snap.satellites) ++count[s.system];
        for (auto c : {Constellation::Gps, Constellation::Glonass, Constellation::Galileo,
                       Constellation::BeiDou, Constellation::Sbas})
            QVERIFY2(count[c] >= 1, toString(c).data());
        QVERIFY(count[Constellation::Gps] >= 5 && count[Constellation::Gps] <= 14);
        QVERIFY(snap.used >= 12);
        QVERIFY(snap.fix == FixKind::Autonomous);
    }
    void tracksAreSmoothAndSatellitesRiseAndSet() {
        SkyModel sky(7);
        std::map<int, std::pair<double, double>> prev; // prn → (el, az) of GPS sats
        int rises = 0, sets = 0;
        auto visible = [&](double t) {
            std::map<int, std::pair<double, double>> now;
            for (const auto &s : sky.geometry(t))
                if (s.system == Constellation::Gps) now[s.prn] = {s.elevation, s.azimuth};
            return now;
        };
        prev = visible(0);
        for (double t = 10; t <= 6 * 3600; t += 10) {
            const auto now = visible(t);
            for (const auto &[prn, ea] : now) {
                auto it = prev.find(prn);
                if (it == prev.end()) {
                    ++rises;
                    QVERIFY2(ea.first < 2.0, "a satellite appears only at the horizon");
                    continue;
                }
                QVERIFY(std::abs(ea.first - it->second.first) < 1.0); // < 1 deg per 10 s
                double daz = std::abs(ea.second - it->second.second);
                if (daz > 180) daz = 360 - daz;
                QVERIFY(daz < 20.0 || ea.first > 80); // near zenith azimuth swings
            }
            for (const auto &[prn, ea] : prev)
                if (!now.count(prn)) {
                    ++sets;
                    QVERIFY(ea.first < 2.0);
                }
            prev = now;
        }
        QVERIFY(rises >= 4);
        QVERIFY(sets >= 4);
    }
    void snrGrowsWithElevation() {
        SkyModel sky(3);
        double lowSum = 0, highSum = 0;
        int low = 0, high = 0;
        for (double t = 0; t < 3600; t += 60) {
            for (const auto &s : sky.update(t, UseMask{}, FixKind::Autonomous, -100).satellites) {
                if (!s.tracked) continue;
                QVERIFY(s.snr >= 10 && s.snr <= 55);
                if (s.elevation < 15) lowSum += s.snr, ++low;
                if (s.elevation > 60) highSum += s.snr, ++high;
            }
        }
        QVERIFY(low > 0 && high > 0);
        QVERIFY(highSum / high > lowSum / low + 8);
    }
    void satellitesBelowTheMaskAreNotUsed() {
        SkyModel sky(5);
        UseMask mask;
        mask.elevationMask = 30;
        const auto snap = sky.update(100, mask, FixKind::Autonomous, -100);
        int below = 0;
        for (const auto &s : snap.satellites) {
            if (s.elevation < 30) {
                QVERIFY(!s.used);
                ++below;
            }
        }
        QVERIFY(below > 0);
        UseMask noGlonass;
        noGlonass.glonass = false;
        for (const auto &s : sky.update(101, noGlonass, FixKind::Autonomous, -100).satellites)
            if (s.system == Constellation::Glonass) QVERIFY(!s.tracked && !s.used);
    }
    void dopsComeFromTheUsedGeometry() {
        // Four satellites: zenith plus three at 0 deg elevation 120 deg apart. Known DOPs.
        std::vector<SimSatellite> sats(4);
        sats[0].elevation = 90;
        for (int i = 1; i < 4; ++i) sats[i].azimuth = 120.0 * (i - 1);
        const Dops d = computeDops(sats);
        QVERIFY(std::abs(d.hdop - std::sqrt(4.0 / 3.0)) < 1e-6);
        QVERIFY(std::abs(d.edop - std::sqrt(2.0 / 3.0)) < 1e-6);
        QVERIFY(std::abs(d.gdop * d.gdop - (d.pdop * d.pdop + d.tdop * d.tdop)) < 1e-6);
        sats.pop_back();
        QCOMPARE(computeDops(sats).pdop, 99.9);
        // A wide sky gives a better PDOP than the same count bunched up.
        SkyModel sky(11);
        const auto snap = sky.update(0, UseMask{}, FixKind::Autonomous, -100);
        QVERIFY(snap.dops.pdop > 0.5 && snap.dops.pdop < 3.0);
        QVERIFY(snap.dops.hdop < snap.dops.pdop && snap.dops.vdop < snap.dops.pdop);
    }
    void positionNoiseFollowsTheFixType() {
        auto spread = [](FixKind k) {
            SkyModel sky(13);
            double maxErr = 0;
            for (double t = 0; t < 600; t += 1) {
                const auto s = sky.update(t, UseMask{}, k, -100);
                maxErr = std::max(maxErr, std::hypot(s.errNorth, s.errEast));
            }
            return maxErr;
        };
        const double autonomous = spread(FixKind::Autonomous), fixed = spread(FixKind::Fixed);
        QVERIFY(autonomous > 0.2 && autonomous < 15);
        QVERIFY(fixed > 0.0005 && fixed < 0.1);
    }
    void sameSeedSameSkyOtherSeedOtherSky() {
        SkyModel a(42), b(42), c(43);
        for (double t = 0; t < 30; t += 1) {
            const auto sa = a.update(t, UseMask{}, FixKind::Autonomous, -100);
            const auto sb = b.update(t, UseMask{}, FixKind::Autonomous, -100);
            QCOMPARE(sa.lat, sb.lat);
            QCOMPARE(sa.satellites.size(), sb.satellites.size());
            for (std::size_t i = 0; i < sa.satellites.size(); ++i)
                QCOMPARE(sa.satellites[i].snr, sb.satellites[i].snr);
        }
        QVERIFY(a.update(31, UseMask{}, FixKind::Autonomous, -100).lat !=
                c.update(31, UseMask{}, FixKind::Autonomous, -100).lat);
    }
};

QTEST_APPLESS_MAIN(TstSimSky)
#include "tst_sim_sky.moc"
