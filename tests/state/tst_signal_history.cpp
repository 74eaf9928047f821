// SignalHistory (protocol/state): C/N0 of each satellite and signal kept at most one sample a
// step (the mean of its epochs), the span dropping what is older, midnight counting a day, the
// polar map's cells (10° of azimuth by 10° of elevation: mean C/N0 and count); and a whole
// simulated log, and a range of it, decoded by historyOfLog.
#include "builtin_registry.h"
#include "sim/receiver.h"
#include "state/epoch.h"
#include "state/signal_history.h"

#include <QTest>

using namespace gnss;

namespace {

Epoch epochAt(std::int64_t ms, std::vector<SatelliteInView> sats) {
    Epoch e;
    e.time = TimeOfDay{ms * 1'000'000, 1};
    e.satellites = std::move(sats);
    return e;
}

SatelliteInView sat(Constellation c, int prn, int snr, int el = 45, int az = 95, int signal = 1) {
    SatelliteInView s;
    s.sat = {c, prn};
    s.signalId = signal;
    s.elevation = el;
    s.azimuth = az;
    s.snr = snr;
    return s;
}

} // namespace

class TstSignalHistory : public QObject {
    Q_OBJECT
private slots:
    void oneSampleAStepTheMeanOfItsEpochs() {
        SignalHistory h(600'000, 1000);
        // 10 Hz for 3 s: G05 at 40 and 42 in turn; R12 from 1 s on.
        for (int i = 0; i < 30; ++i) {
            std::vector<SatelliteInView> s{sat(Constellation::Gps, 5, i % 2 ? 42 : 40)};
            if (i >= 10) s.push_back(sat(Constellation::Glonass, 12, 30, 80, 200));
            QVERIFY(h.add(epochAt(36'000'000 + i * 100, s)));
        }
        // A fourth second closes the third.
        h.add(epochAt(36'003'000, {sat(Constellation::Gps, 5, 50)}));
        const auto &g = h.series().at({{Constellation::Gps, 5}, 1});
        QCOMPARE(g.size(), std::size_t(3));
        QCOMPARE(g[0].timeMs, std::int64_t(36'000'000));
        QCOMPARE(g[0].cn0, 41.0f);
        const auto &r = h.series().at({{Constellation::Glonass, 12}, 1});
        QCOMPARE(r.size(), std::size_t(2));
        QCOMPARE(h.epochs(), std::uint64_t(31));
        QVERIFY(!h.add(Epoch{})); // no time: skipped
    }

    void theSpanDropsWhatIsOlder() {
        SignalHistory h(10'000, 1000);
        for (int s = 0; s < 60; ++s) h.add(epochAt(s * 1000, {sat(Constellation::Gps, 1, 40)}));
        const auto &g = h.series().at({{Constellation::Gps, 1}, 1});
        QVERIFY(g.size() <= 11);
        QVERIFY(g.front().timeMs >= 49'000);
        QCOMPARE(h.oldestMs(), g.front().timeMs);
    }

    void midnightCountsADay() {
        SignalHistory h(0, 1000);
        h.add(epochAt(86'399'000, {sat(Constellation::Gps, 1, 40)}));
        h.add(epochAt(0, {sat(Constellation::Gps, 1, 40)}));
        h.add(epochAt(1000, {sat(Constellation::Gps, 1, 40)}));
        QCOMPARE(h.newestMs(), std::int64_t(86'401'000));
        QCOMPARE(h.series().begin()->second.back().timeMs, std::int64_t(86'400'000));
    }

    void thePolarMapHasCellsOfTenDegrees() {
        SignalHistory h;
        h.add(epochAt(0, {sat(Constellation::Gps, 1, 40, 45, 95),
                          sat(Constellation::Gps, 2, 20, 47, 99)}));
        h.add(epochAt(1000, {sat(Constellation::Gps, 1, 30, 45, 95)}));
        // Azimuth 95 and 99 are cell 9, elevation 45 and 47 cell 4.
        const SignalHistory::Cell &c = h.cell(9, 4);
        QCOMPARE(c.count, 3u);
        QCOMPARE(c.mean(), 30.0);
        QCOMPARE(h.cell(0, 0).count, 0u);
        // The horizon and the zenith have cells too; azimuth 360 is north.
        h.add(epochAt(2000, {sat(Constellation::Gps, 3, 35, 90, 360),
                             sat(Constellation::Gps, 4, 25, 0, 359)}));
        QCOMPARE(h.cell(0, 8).count, 1u);
        QCOMPARE(h.cell(35, 0).count, 1u);
    }

    // A simulated receiver's hour, decoded front to back as a log.
    void aWholeLog() {
        auto rx = sim::builtinSimulators().make("nvs", {});
        std::string log;
        std::size_t at200 = 0, at300 = 0;
        for (int s = 0; s < 600; ++s) {
            if (s == 200) at200 = log.size();
            if (s == 300) at300 = log.size();
            rx->advance(1.0);
            log += rx->takeOutput();
        }
        const SignalHistory h = historyOfLog(log, test::builtinRegistry(), 10'000);
        QVERIFY(h.epochs() >= 590);
        QVERIFY(h.series().size() >= 10);
        for (const auto &[key, samples] : h.series()) {
            QVERIFY(key.sat.system != Constellation::Unknown);
            QVERIFY(samples.size() <= 61); // one a step of 10 s
            for (const auto &x : samples) QVERIFY(x.cn0 > 10 && x.cn0 < 60);
        }
        // A range (the log viewer's selection): its epochs alone, over its own time.
        const std::string_view range = std::string_view(log).substr(at200, at300 - at200);
        const SignalHistory r = historyOfLog(range, test::builtinRegistry(), 1000,
                                             test::builtinRegistry().find("nvs"));
        const auto sixth = h.epochs() / 6; // 100 s of 600, whatever the rate
        QVERIFY2(r.epochs() + 6 >= sixth && r.epochs() <= sixth + 6,
                 QByteArray::number(qulonglong(r.epochs())));
        QVERIFY(r.newestMs() - r.oldestMs() >= 98'000 && r.newestMs() - r.oldestMs() <= 100'000);
        std::atomic<bool> cancel{true};
        QCOMPARE(historyOfLog(log, test::builtinRegistry(), 1000, nullptr, &cancel).epochs(),
                 std::uint64_t(0));
    }
};

QTEST_GUILESS_MAIN(TstSignalHistory)
#include "tst_signal_history.moc"
