// The simulator's RTK base station: valid frames at the right rates, MSM4s whose satellites are
// those above the horizon, whose pseudoranges follow the geometry and whose CNR is the sky
// model's SNR, GPS and GLONASS epoch times, and the configured position in 1005.
#include "rtcm/bit_reader.h"
#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_messages.h"
#include "sim/rtcm_base_station.h"

#include <QTest>

#include <cmath>
#include <map>

using namespace gnss;
using namespace gnss::sim;

namespace {

struct Frame {
    std::string bytes;
    rtcm::RtcmMessage message;
    std::vector<std::uint8_t> payload;
};

std::vector<Frame> framesOf(const std::string &stream, rtcm::RtcmFramerStats *stats = nullptr) {
    rtcm::RtcmFramer framer;
    std::vector<Frame> out;
    auto keep = [&](const rtcm::RtcmFrame &f) {
        Frame fr;
        fr.bytes.assign(reinterpret_cast<const char *>(f.bytes.data()), f.bytes.size());
        fr.payload.assign(f.payload().begin(), f.payload().end());
        fr.message = rtcm::decodeMessage(f.payload());
        out.push_back(std::move(fr));
    };
    framer.feed(stream, keep);
    framer.finish(keep);
    if (stats) *stats = framer.stats();
    return out;
}

// One satellite of an MSM4 body read back: range (metres) and CNR.
struct MsmSat {
    unsigned id = 0;
    double rangeMetres = 0;
    unsigned cnr = 0;
    unsigned lock = 0;
};

std::vector<MsmSat> readMsm4(const Frame &f) {
    const auto &h = std::get<rtcm::MsmHeader>(f.message.body);
    const unsigned n = h.satelliteCount;
    rtcm::BitReader r(f.payload, rtcm::kMsmHeaderBits + std::size_t(n) * h.signalCount);
    std::vector<MsmSat> sats(n);
    std::vector<double> rough(n);
    for (unsigned i = 0; i < n; ++i) rough[i] = double(r.u(8));
    for (unsigned i = 0; i < n; ++i) rough[i] += double(r.u(10)) / 1024;
    for (unsigned i = 0; i < n; ++i) {
        sats[i].id = h.satellites[i];
        sats[i].rangeMetres = (rough[i] + double(r.s(15)) / 16777216.0) * 299792.458;
    }
    for (unsigned i = 0; i < n; ++i) r.s(22);
    for (unsigned i = 0; i < n; ++i) sats[i].lock = unsigned(r.u(4));
    for (unsigned i = 0; i < n; ++i) r.u(1);
    for (unsigned i = 0; i < n; ++i) sats[i].cnr = unsigned(r.u(6));
    return r.ok() ? sats : std::vector<MsmSat>{};
}

const Frame *find(const std::vector<Frame> &frames, unsigned number) {
    for (const Frame &f : frames)
        if (f.message.number == number) return &f;
    return nullptr;
}

} // namespace

class TstRtcmBaseStation : public QObject {
    Q_OBJECT
private slots:
    void framesAreValidAndComeAtTheirRates() {
        RtcmBaseStation base;
        base.advance(0);
        base.advance(10.0);
        rtcm::RtcmFramerStats stats;
        const std::string stream = base.takeOutput();
        const auto frames = framesOf(stream, &stats);
        QCOMPARE(stats.crcFailures, std::uint64_t(0));
        QCOMPARE(stats.bytesSkipped, std::uint64_t(0));
        QCOMPARE(stats.bytesInFrames, std::uint64_t(stream.size()));
        std::map<unsigned, int> counts;
        for (const Frame &f : frames) {
            ++counts[f.message.number];
            QVERIFY2(f.message.error.empty(), f.message.error.data());
            QCOMPARE(f.message.station.value_or(9999), 1u);
        }
        QCOMPARE(base.epochs(), std::uint64_t(11)); // t = 0 .. 10
        QCOMPARE(counts[1074], 11);
        QCOMPARE(counts[1084], 11);
        QCOMPARE(counts[1005], 11);
        QCOMPARE(counts[1230], 2); // t = 0 and t = 10
    }

    void epochTimesAreGpsAndGlonassTime_data() {
        QTest::addColumn<double>("time");
        QTest::newRow("the start") << 0.0;
        QTest::newRow("a minute in") << 60.0;
    }
    void epochTimesAreGpsAndGlonassTime() {
        QFETCH(double, time);
        RtcmBaseStation base;
        base.advance(time);
        const auto frames = framesOf(base.takeOutput());
        const Frame *gps = nullptr, *glo = nullptr;
        for (const Frame &f : frames) { // the last epoch's
            if (f.message.number == 1074) gps = &f;
            if (f.message.number == 1084) glo = &f;
        }
        QVERIFY(gps && glo);
        const auto &g = std::get<rtcm::MsmHeader>(gps->message.body);
        const auto &r = std::get<rtcm::MsmHeader>(glo->message.body);
        // 2024-03-15 10:00:00 UTC: Friday, GPS = UTC + 18 s; GLONASS = UTC + 3 h.
        QCOMPARE(g.epochMs, std::uint32_t((5 * 86400 + 36000 + 18 + time) * 1000));
        QCOMPARE(r.epochMs, std::uint32_t((13 * 3600 + time) * 1000));
        QCOMPARE(r.gloDayOfWeek.value_or(9), 5u);
        QVERIFY(g.multipleMessage);  // the GLONASS MSM of the same epoch follows
        QVERIFY(!r.multipleMessage); // the last of the epoch
    }

    void satelliteMasksAreTheSatellitesAboveTheHorizon() {
        RtcmBaseStation base;
        base.advance(0);
        const auto frames = framesOf(base.takeOutput());
        for (auto [number, system] :
             {std::pair{1074u, Constellation::Gps}, std::pair{1084u, Constellation::Glonass}}) {
            const Frame *f = find(frames, number);
            QVERIFY(f);
            const auto &h = std::get<rtcm::MsmHeader>(f->message.body);
            std::vector<unsigned> expected, got;
            for (const SimSatellite &s : base.lastSky().satellites)
                if (s.system == system && s.elevation > 0) expected.push_back(unsigned(s.prn));
            for (auto id : h.satelliteIds()) got.push_back(id);
            QVERIFY(expected.size() >= 4);
            QCOMPARE(got, expected);
            QCOMPARE(h.signalCount, std::uint8_t(1));
            QCOMPARE(std::string(rtcm::msmSignalName(h.system, h.signalIds().front())),
                     std::string("1C"));
        }
    }

    void pseudorangesFollowTheGeometryAndCnrTheSnr() {
        RtcmBaseStation base;
        base.advance(0);
        const auto frames = framesOf(base.takeOutput());
        const double rBase = 6364000; // roughly, at 55.75 N (only for the plausibility bounds)
        const SkyModel model(1);      // the same orbits the base's model flies
        for (auto [number, system] :
             {std::pair{1074u, Constellation::Gps}, std::pair{1084u, Constellation::Glonass}}) {
            const auto sats = readMsm4(*find(frames, number));
            QVERIFY(!sats.empty());
            for (const MsmSat &m : sats) {
                const SimSatellite *s = nullptr;
                for (const SimSatellite &k : base.lastSky().satellites)
                    if (k.system == system && unsigned(k.prn) == m.id) s = &k;
                QVERIFY(s);
                double radius = 0;
                for (const SkyModel::Orbit &o : model.orbits())
                    if (o.system == system && unsigned(o.prn) == m.id) radius = o.radius;
                // Between straight up (radius − R) and the horizon (sqrt(radius² − R²)).
                QVERIFY2(m.rangeMetres > radius - rBase - 20000 &&
                                 m.rangeMetres < std::sqrt(radius * radius - rBase * rBase) + 20000,
                         qPrintable(QString::number(m.rangeMetres)));
                QCOMPARE(m.cnr, unsigned(std::lround(s->snr)));
                QCOMPARE(m.lock, 15u); // tracking for longer than 524 s
            }
            // Higher satellites are nearer.
            for (const MsmSat &a : sats)
                for (const MsmSat &b : sats) {
                    double ea = 0, eb = 0;
                    for (const SimSatellite &k : base.lastSky().satellites)
                        if (k.system == system) {
                            if (unsigned(k.prn) == a.id) ea = k.elevation;
                            if (unsigned(k.prn) == b.id) eb = k.elevation;
                        }
                    if (ea > eb + 5) QVERIFY(a.rangeMetres < b.rangeMetres);
                }
        }
    }

    void stationPositionIsTheConfiguredOne() {
        BaseStationConfig c;
        c.latDeg = -33.8568;
        c.lonDeg = 151.2153;
        c.height = 42.5;
        c.stationId = 4095;
        RtcmBaseStation base(c);
        base.advance(0);
        const std::vector<Frame> frames = framesOf(base.takeOutput()); // f points into it
        const Frame *f = find(frames, 1005);
        QVERIFY(f);
        const auto &arp = std::get<rtcm::StationArp>(f->message.body);
        QCOMPARE(arp.station, 4095u);
        QVERIFY(arp.gps && arp.glonass && !arp.galileo);
        QVERIFY(arp.position);
        QVERIFY(std::fabs(arp.position->latDeg - c.latDeg) < 1e-8);
        QVERIFY(std::fabs(arp.position->lonDeg - c.lonDeg) < 1e-8);
        QVERIFY(std::fabs(arp.position->height - c.height) < 0.001);
    }

    void theSameSeedGivesTheSameStream() {
        RtcmBaseStation a, b;
        a.advance(5.5);
        b.advance(2.25);
        b.advance(3.25);
        QCOMPARE(a.takeOutput(), b.takeOutput());
        BaseStationConfig other;
        other.seed = 2;
        RtcmBaseStation c(other);
        c.advance(5.5);
        RtcmBaseStation d;
        d.advance(5.5);
        QVERIFY(c.takeOutput() != d.takeOutput());
    }
};

QTEST_APPLESS_MAIN(TstRtcmBaseStation)
#include "tst_rtcm_base_station.moc"
