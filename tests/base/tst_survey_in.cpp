// The workbench's survey-in (base/survey_in.h): its mean, σ east/north/up and the mean's accuracy
// on positions drawn about a known point; the goals by time and by accuracy; the convergence.
#include "base/receiver_clock.h"
#include "base/survey_in.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace gnss;
using namespace gnss::base;

namespace {

const wgs84::Geodetic kTruth{55.7512, 37.6184, 166.6};

// A position `e`, `n`, `u` metres from the truth.
wgs84::Geodetic offset(double e, double n, double u) {
    const double mPerDegLat = 111132.95, mPerDegLon = 111319.49 * std::cos(wgs84::radians(55.7512));
    return {kTruth.latDeg + n / mPerDegLat, kTruth.lonDeg + e / mPerDegLon, kTruth.height + u};
}

} // namespace

class TstSurveyIn : public QObject {
    Q_OBJECT
private slots:
    void theMeanAndTheSpreadOfNoisyFixes() {
        SurveyIn s;
        std::mt19937 rng(3);
        std::normal_distribution<double> e(0, 1.0), n(0, 2.0), u(0, 3.0);
        for (int i = 0; i < 20000; ++i) s.add(i * 0.1, offset(e(rng), n(rng), u(rng)));
        const SurveyStatus st = s.status();
        QCOMPARE(st.count, std::size_t(20000));
        QVERIFY(std::abs(st.seconds - 1999.9) < 1e-6);
        QVERIFY2(std::abs(st.sigmaEast - 1.0) < 0.03, qPrintable(QString::number(st.sigmaEast)));
        QVERIFY2(std::abs(st.sigmaNorth - 2.0) < 0.05, qPrintable(QString::number(st.sigmaNorth)));
        QVERIFY2(std::abs(st.sigmaUp - 3.0) < 0.08, qPrintable(QString::number(st.sigmaUp)));
        // The mean is within a few σ/√n of the truth, and its accuracy says so.
        const double expected = std::sqrt(1 + 4 + 9) / std::sqrt(20000.0);
        QVERIFY(std::abs(st.accuracy - expected) < expected * 0.05);
        const wgs84::Ecef t = wgs84::toEcef(kTruth);
        QVERIFY(std::hypot(st.meanEcef.x - t.x, st.meanEcef.y - t.y, st.meanEcef.z - t.z) <
                4 * expected);
        QVERIFY(std::abs(st.mean.height - kTruth.height) < 4 * 3 / std::sqrt(20000.0));
    }

    void aGoalByTime() {
        SurveyIn s({.seconds = 60});
        for (int i = 0; i <= 59; ++i) s.add(i, offset(i % 2, 0, 0));
        QVERIFY(!s.done());
        QVERIFY(s.progress() > 0.95 && s.progress() < 1);
        s.add(60, kTruth);
        QVERIFY(s.done());
        QCOMPARE(s.progress(), 1.0);
    }

    void aGoalByAccuracyNeedsEnoughPositions() {
        SurveyIn s({.accuracy = 0.5});
        // Identical fixes: accuracy 0 from the second, but not before the minimum count.
        for (int i = 0; i < 9; ++i) s.add(i, kTruth);
        QVERIFY(!s.done());
        s.add(9, kTruth);
        QVERIFY(s.done());
        // Noisy fixes: done once σ/√n reaches the goal.
        SurveyIn t({.accuracy = 0.2});
        std::mt19937 rng(5);
        std::normal_distribution<double> noise(0, 1.0);
        int i = 0;
        while (!t.done() && i < 10000) t.add(i++, offset(noise(rng), noise(rng), noise(rng)));
        QVERIFY(t.done());
        QVERIFY2(i > 50 && i < 150, qPrintable(QString::number(i))); // (√3 / 0.2)² = 75
        QVERIFY(t.status().accuracy <= 0.2);
    }

    void theConvergenceIsKept() {
        SurveyIn s;
        for (int i = 0; i < 100; ++i) s.add(i * 0.2, offset(i < 50 ? 2 : -2, 0, 0));
        const auto &h = s.history();
        QCOMPARE(h.size(), std::size_t(20)); // one a second
        QVERIFY(std::abs(h.front().east) < 1e-6);
        QVERIFY(h.back().east < -1.5 && h.back().east > -2.5); // from the first position
        QVERIFY(h.back().accuracy > 0);
    }

    // The receiver's clock goes on across midnight, and waits for a time.
    void theReceiverClockCrossesMidnight() {
        base::ReceiverClock c;
        c.add(std::nullopt);
        QVERIFY(!c.timed());
        c.add(TimeOfDay{86399'500'000'000LL});
        QVERIFY(c.timed());
        c.add(std::nullopt);
        QCOMPARE(c.seconds(), 86399.5);
        c.add(TimeOfDay{500'000'000LL});
        QCOMPARE(c.seconds(), 86400.5);
        c.add(TimeOfDay{400'000'000LL}); // a step back (a repeated epoch) is no new day
        QCOMPARE(c.seconds(), 86400.4);
    }

    void nothingYet() {
        SurveyIn s({.seconds = 1});
        QCOMPARE(s.status().count, std::size_t(0));
        QVERIFY(!s.done());
        QCOMPARE(s.progress(), 0.0);
    }
};

QTEST_GUILESS_MAIN(TstSurveyIn)
#include "tst_survey_in.moc"
