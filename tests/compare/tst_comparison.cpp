// The comparison of receivers (protocol/compare): epochs matched on UTC time (a time one
// receiver skipped is not matched, midnight counts a day), the east/north/up difference of a
// known offset, C/N0 side by side per satellite and signal (and by each one's first signal when
// the receivers number levels differently), satellites only one tracks, the statistics; and
// end to end on two simulated receivers of one sky, one told to report a known offset, C/N0 and
// dropped satellites: the report gives back what it was told.
#include "builtin_registry.h"
#include "compare/comparison.h"
#include "compare/comparison_json.h"
#include "core/json_writer.h"
#include "core/stream_decoder.h"
#include "core/wgs84.h"
#include "sim/receiver.h"
#include "state/epoch_assembler.h"

#include <deque>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace gnss;
using namespace gnss::compare;

namespace {

Observation at(std::int64_t ms, double lat = 55.75, double lon = 37.62, double h = 160,
               std::vector<SignalLevel> levels = {}) {
    Observation o;
    o.timeMs = ms;
    o.fix = FixType::Fix3D;
    o.lat = lat;
    o.lon = lon;
    o.height = h;
    o.levels = std::move(levels);
    return o;
}

SatelliteRef gps(int prn) {
    return {Constellation::Gps, prn};
}

// The epochs of a simulated receiver run for `seconds`, as observations.
std::vector<Observation> simulated(const char *dialect, const sim::SimOptions &options,
                                   double seconds) {
    auto rx = sim::builtinSimulators().make(dialect, options);
    StreamDecoder decoder(test::builtinRegistry());
    EpochAssembler assembler(test::builtinRegistry().find(dialect));
    std::vector<Observation> out;
    auto keep = [&](const Epoch &e) {
        if (auto o = Observation::of(e)) out.push_back(std::move(*o));
    };
    for (double t = 0; t < seconds; t += 0.5) {
        rx->advance(0.5);
        decoder.feed(rx->takeOutput(), [&](const SentenceEvent &ev) {
            if (ev.message) assembler.add(ev.sentence, *ev.message, keep);
        });
    }
    assembler.flush(keep);
    return out;
}

QJsonObject reportJson(const Report &r) {
    std::string s;
    JsonWriter w(s);
    writeReportJson(w, r);
    return QJsonDocument::fromJson(QByteArray::fromStdString(s)).object();
}

} // namespace

class TstComparison : public QObject {
    Q_OBJECT
private slots:
    void aKnownOffsetIsMeasuredEastNorthUp() {
        const auto m = wgs84::metresPerDegree(55.75);
        const Observation ref = at(0);
        const Observation other = at(0, 55.75 - 0.2 / m.north, 37.62 + 0.3 / m.east, 160.5);
        const Difference d = Comparison::differenceOf(ref, other);
        QVERIFY(d.east && d.north && d.up && d.horizontal);
        QVERIFY(std::abs(*d.east - 0.3) < 1e-6);
        QVERIFY(std::abs(*d.north + 0.2) < 1e-6);
        QVERIFY(std::abs(*d.up - 0.5) < 1e-9);
        QVERIFY(std::abs(*d.horizontal - std::hypot(0.3, 0.2)) < 1e-6);
        // Across the antimeridian the short way round.
        const Difference w = Comparison::differenceOf(at(0, 0, 179.99999), at(0, 0, -179.99999));
        QVERIFY(std::abs(*w.east - 0.00002 * wgs84::metresPerDegree(0).east) < 1e-6);
        // No position, no difference.
        Observation none = at(0);
        none.fix = FixType::None;
        QVERIFY(!Comparison::differenceOf(ref, none).horizontal);
    }

    void cn0SideBySideAndSatellitesOnlyOneTracks() {
        const Observation ref = at(0, 55.75, 37.62, 160,
                                   {{gps(1), 1, 45},
                                    {gps(1), 7, 40},
                                    {gps(2), 1, 38},
                                    {{Constellation::Glonass, 3}, 0, 41}});
        const Observation other = at(0, 55.75, 37.62, 160,
                                     {{gps(1), 1, 42},
                                      {gps(1), 7, 39},
                                      {gps(5), 1, 30},
                                      {{Constellation::Glonass, 3}, 1, 44}});
        const Difference d = Comparison::differenceOf(ref, other);
        QCOMPARE(int(d.cn0.size()), 3);
        QCOMPARE(d.cn0[0].other - d.cn0[0].reference, -3); // G01 L1
        QCOMPARE(d.cn0[1].other - d.cn0[1].reference, -1); // G01 L5
        // R03: signal 0 (not said) against 1: each one's first signal.
        QCOMPARE(d.cn0[2].sat, (SatelliteRef{Constellation::Glonass, 3}));
        QCOMPARE(d.cn0[2].other - d.cn0[2].reference, 3);
        QCOMPARE(d.onlyInReference, std::vector<SatelliteRef>{gps(2)});
        QCOMPARE(d.onlyInOther, std::vector<SatelliteRef>{gps(5)});
    }

    void epochsAreMatchedOnUtcTime() {
        Comparison c({"A", "B", "C"});
        std::vector<std::int64_t> matched;
        auto onMatch = [&](const Match &m) { matched.push_back(m.timeMs); };
        // B skips 1000; C comes late; A's 3000 never gets company.
        for (std::int64_t t : {0, 1000, 2000, 3000}) c.add(0, at(t), onMatch);
        for (std::int64_t t : {0, 2000}) c.add(1, at(t), onMatch);
        for (std::int64_t t : {0, 1000, 2000}) c.add(2, at(t), onMatch);
        QCOMPARE(matched, (std::vector<std::int64_t>{0, 2000}));
        QCOMPARE(c.matchedEpochs(), std::size_t(2));
        // An epoch older than the last match is too late to match.
        c.add(1, at(1000), onMatch);
        QCOMPARE(c.matchedEpochs(), std::size_t(2));
        const Report r = c.report();
        QCOMPARE(r.receivers[0].epochs, std::size_t(4));
        QCOMPARE(r.receivers[1].epochs, std::size_t(3));
        QCOMPARE(int(r.pairs.size()), 2);
    }

    void midnightCountsADay() {
        Comparison c({"A", "B"});
        std::vector<std::int64_t> matched;
        auto onMatch = [&](const Match &m) { matched.push_back(m.timeMs); };
        for (std::int64_t t : {86'399'000, 0, 1000}) {
            c.add(0, at(t), onMatch);
            c.add(1, at(t), onMatch);
        }
        QCOMPARE(matched, (std::vector<std::int64_t>{86'399'000, 0, 1000}));
    }

    void aSilentReceiverCostsNoMemory() {
        Comparison c({"A", "B"});
        for (std::int64_t t = 0; t < 3'600'000; t += 100) c.add(0, at(t));
        QCOMPARE(c.matchedEpochs(), std::size_t(0));
        // What A holds is at most kHoldMs of epochs: B arriving now matches only the recent.
        int matched = 0;
        c.add(1, at(3'599'900), [&](const Match &) { ++matched; });
        c.add(1, at(100), [&](const Match &) { ++matched; });
        QCOMPARE(matched, 1);
    }

    void statisticsOverTheMatchedEpochs() {
        Comparison c({"ref", "other"});
        const auto m = wgs84::metresPerDegree(55.75);
        // East offsets 0.0 .. 0.99 m in steps of 1 cm, north 0.
        for (int i = 0; i < 100; ++i) {
            c.add(0, at(i * 1000, 55.75, 37.62, 160, {{gps(1), 1, 40}}));
            c.add(1, at(i * 1000, 55.75, 37.62 + (i / 100.0) / m.east, 160.25, {{gps(1), 1, 37}}));
        }
        const Report r = c.report();
        QCOMPARE(r.matchedEpochs, std::size_t(100));
        const PairReport &p = r.pairs.at(0);
        QVERIFY(std::abs(p.east.mean - 0.495) < 1e-6);
        QVERIFY(std::abs(p.east.median - 0.495) < 1e-6);
        QVERIFY(std::abs(p.east.p95 - 0.9405) < 1e-6);
        QVERIFY(std::abs(p.cep50 - 0.495) < 1e-6);
        QVERIFY(std::abs(p.cep95 - 0.9405) < 1e-6);
        QVERIFY(std::abs(p.up.mean - 0.25) < 1e-9);
        QCOMPARE(p.cn0.mean, -3.0);
        QVERIFY(p.perConstellation.at(0).system == Constellation::Gps);
        QCOMPARE(p.perConstellation.at(0).satellites, 1);
        const QJsonObject j = reportJson(r);
        QCOMPARE(j["matched_epochs"].toInt(), 100);
        const QJsonObject other = j["receivers"].toArray().at(1).toObject();
        QCOMPARE(other["difference_m"].toObject()["east"].toObject()["mean"].toDouble(), 0.495);
        QCOMPARE(other["cn0_db"]
                         .toObject()["per_constellation"]
                         .toObject()["GPS"]
                         .toObject()["mean"]
                         .toDouble(),
                 -3.0);
        QCOMPARE(j["receivers"].toArray().at(0).toObject()["fix"].toObject()["3d"].toDouble(), 1.0);
    }

    // A window of the last matches (the Compare dock's) gives the report of those alone, with
    // the whole run's numbers when it holds every match.
    void aWindowOfMatchesHasItsOwnReport() {
        Comparison c({"ref", "other"});
        const auto m = wgs84::metresPerDegree(55.75);
        std::deque<MatchRecord> all, last10;
        for (int i = 0; i < 100; ++i) {
            c.add(0, at(i * 1000, 55.75, 37.62, 160, {{gps(1), 1, 40}, {gps(2), 1, 30}}));
            c.add(1, at(i * 1000, 55.75, 37.62 + (i / 100.0) / m.east, 160, {{gps(1), 1, 37}}),
                  [&](const Match &match) {
                      all.push_back(MatchRecord::of(match));
                      last10.push_back(all.back());
                      if (last10.size() > 10) last10.pop_front();
                  });
        }
        QCOMPARE(all.size(), std::size_t(100));
        QCOMPARE(all.back().fixes, (std::vector<FixType>{FixType::Fix3D, FixType::Fix3D}));
        const Report whole = c.report(), window = Comparison::reportOf({"ref", "other"}, all);
        QCOMPARE(window.matchedEpochs, whole.matchedEpochs);
        QCOMPARE(window.pairs.at(0).east.mean, whole.pairs.at(0).east.mean);
        QCOMPARE(window.pairs.at(0).cep95, whole.pairs.at(0).cep95);
        QCOMPARE(window.pairs.at(0).onlyInReference.at(0).epochs, std::size_t(100));
        QCOMPARE(window.receivers.at(1).fixes.at(0).epochs, std::size_t(100));
        // The last ten: east 0.90 .. 0.99 m.
        const Report recent = Comparison::reportOf({"ref", "other"}, last10);
        QCOMPARE(recent.matchedEpochs, std::size_t(10));
        QVERIFY(std::abs(recent.pairs.at(0).east.mean - 0.945) < 1e-6);
        QCOMPARE(recent.pairs.at(0).onlyInReference.at(0).epochs, std::size_t(10));
    }

    // Two simulated receivers of one sky (same seed); the second told to differ. The report
    // gives back what it was told, to the NMEA digits' resolution.
    void simulatorsToldHowToDifferAreMeasured() {
        sim::SimOptions plain;
        sim::SimOptions told = plain;
        std::string error;
        told.differences = *sim::parseOffset("0.3,-0.2,0.5", told.differences, error);
        told.differences = *sim::parseCn0Offset("GPS:-3,GLONASS:2", told.differences, error);
        told.differences = *sim::parseDrop("G05,R12", told.differences, error);
        const auto a = simulated("nmea", plain, 120), b = simulated("nmea", told, 120);
        QVERIFY(a.size() > 100 && b.size() > 100);
        Comparison c({"reference", "told"});
        c.addInTimeOrder({a, b});
        const Report r = c.report();
        QVERIFY2(r.matchedEpochs + 2 >= a.size(), qPrintable(QString::number(r.matchedEpochs)));
        const PairReport &p = r.pairs.at(0);
        QVERIFY2(std::abs(p.east.mean - 0.3) < 0.01, qPrintable(QString::number(p.east.mean)));
        QVERIFY2(std::abs(p.north.mean + 0.2) < 0.01, qPrintable(QString::number(p.north.mean)));
        QVERIFY2(std::abs(p.up.mean - 0.5) < 0.01, qPrintable(QString::number(p.up.mean)));
        bool gpsSeen = false, glonassSeen = false;
        for (const ConstellationCn0 &k : p.perConstellation) {
            if (k.system == Constellation::Gps) {
                gpsSeen = true;
                QVERIFY2(std::abs(k.difference.mean + 3) < 0.01,
                         qPrintable(QString::number(k.difference.mean)));
            }
            if (k.system == Constellation::Glonass) {
                glonassSeen = true;
                QVERIFY(std::abs(k.difference.mean - 2) < 0.01);
            }
            if (k.system == Constellation::Galileo) QVERIFY(std::abs(k.difference.mean) < 0.01);
        }
        QVERIFY(gpsSeen && glonassSeen);
        // The dropped ones are the reference's alone (when they were in view).
        for (const SatelliteCount &s : p.onlyInReference)
            QVERIFY2(s.sat == gps(5) || s.sat == (SatelliteRef{Constellation::Glonass, 12}),
                     satelliteLabel(s.sat).c_str());
        QVERIFY(p.onlyInThis.empty());
    }
};

QTEST_GUILESS_MAIN(TstComparison)
#include "tst_comparison.moc"
