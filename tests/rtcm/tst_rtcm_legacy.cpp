// Legacy RTK observables 1001-1004 (GPS) and 1009-1012 (GLONASS): round trips through the encoder
// for each number, fields checked by hand against the DF definitions, invalid markers, short
// payloads, the JSON and the view shared with MSM.
#include "rtcm/bit_writer.h"
#include "rtcm/observed_signals.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_json.h"
#include "rtcm_test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace gnss::rtcm;
using namespace rtcm_test;

namespace {

// Three satellites with ranges of a real sky (20 000-25 000 km), every value at a resolution
// step or between; the third has no L1 phase and no L2 pseudorange (sent as invalid).
LegacyObservables sample(unsigned number) {
    LegacyObservables o{.number = number, .station = number, .epochMs = 0};
    const bool glo = o.system() == System::Glonass;
    o.epochMs = glo ? 86399000u : 604799000u;
    o.synchronous = number % 2 == 0;
    o.smoothing = true;
    o.smoothingInterval = number % 8;
    const double ranges[] = {20123456.78, 22876543.21, 24999999.99};
    for (unsigned i = 0; i < 3; ++i) {
        LegacySatellite s;
        s.id = glo ? 24 - 7 * i : 2 + 10 * i;
        if (glo) s.frequencyChannel = int(i) * 5 - 7; // −7, −2, +3
        s.l1 = {.code = i % 2,
                .pseudorange = ranges[i],
                .phaseRange = ranges[i] + 12.3456 * (i == 1 ? -1 : 1),
                .lockTime = 20 * i + 7,
                .cnr = 35.25 + i};
        if (i == 2) s.l1.phaseRange.reset();
        s.l2 = LegacySignal{.code = i,
                            .pseudorange = ranges[i] + 3.21 - 2 * double(i),
                            .phaseRange = ranges[i] - 101.1234,
                            .lockTime = 127 - i,
                            .cnr = 30.0 + i};
        if (i == 2) s.l2->pseudorange.reset();
        o.satellites.push_back(s);
    }
    return o;
}

const LegacyObservables *legacyOf(const RtcmMessage &m) {
    return std::get_if<LegacyObservables>(&m.body);
}

bool near(std::optional<double> a, std::optional<double> b, double tolerance) {
    if (!a || !b) return a.has_value() == b.has_value();
    return std::fabs(*a - *b) <= tolerance;
}

// Sent without the ambiguity, the L1 pseudorange comes back modulo its range (1 or 2 light-ms).
std::optional<double> sentRange(std::optional<double> metres, bool ambiguous, System s) {
    if (!metres || !ambiguous) return metres;
    const double unit = s == System::Glonass ? 599584.916 : 299792.458;
    return *metres - std::floor(*metres / unit) * unit;
}

QJsonObject jsonObjectOf(const RtcmMessage &m) {
    std::string out;
    gnss::JsonWriter w(out);
    writeRtcmJson(w, m);
    return QJsonDocument::fromJson(QByteArray::fromStdString(out)).object();
}

} // namespace

class TstRtcmLegacy : public QObject {
    Q_OBJECT
private slots:
    void everyNumberRoundTripsWithinResolution_data() {
        QTest::addColumn<uint>("number");
        QTest::addColumn<uint>("satelliteBits");
        const unsigned bits[] = {58, 74, 101, 125, 64, 79, 107, 130};
        const unsigned numbers[] = {1001, 1002, 1003, 1004, 1009, 1010, 1011, 1012};
        for (int i = 0; i < 8; ++i) QTest::addRow("%u", numbers[i]) << numbers[i] << bits[i];
    }
    void everyNumberRoundTripsWithinResolution() {
        QFETCH(uint, number);
        QFETCH(uint, satelliteBits);
        const LegacyObservables o = sample(number);
        const RtcmMessage m = decodeFrame(encodeLegacy(o));
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.number, number);
        QCOMPARE(m.station, std::optional<unsigned>(o.station));
        const std::size_t header = number >= 1009 ? 61 : 64;
        QCOMPARE(legacySatelliteBits(number), std::size_t(satelliteBits));
        QCOMPARE(m.length, (header + 3 * satelliteBits + 7) / 8);
        const LegacyObservables *d = legacyOf(m);
        QVERIFY(d);
        QCOMPARE(d->number, number);
        QCOMPARE(d->epochMs, o.epochMs);
        QCOMPARE(d->synchronous, o.synchronous);
        QCOMPARE(d->smoothing, o.smoothing);
        QCOMPARE(d->smoothingInterval, o.smoothingInterval);
        QCOMPARE(d->satellites.size(), o.satellites.size());
        const bool ambiguous = !o.extended();
        for (std::size_t i = 0; i < o.satellites.size(); ++i) {
            const LegacySatellite &want = o.satellites[i], &got = d->satellites[i];
            QCOMPARE(got.id, want.id);
            QCOMPARE(got.frequencyChannel, want.frequencyChannel);
            QCOMPARE(got.ambiguity.has_value(), o.extended());
            QCOMPARE(got.l1.code, want.l1.code);
            QCOMPARE(got.l1.lockTime, want.l1.lockTime);
            // Half a step: 0.01 m for pseudoranges, 0.25 mm for phase ranges (then relative to
            // the L1 pseudorange sent, so up to 0.01 m more), 0.125 dB-Hz for CNR.
            const auto l1 = sentRange(want.l1.pseudorange, ambiguous, o.system());
            const double shift = l1 ? *want.l1.pseudorange - *l1 : 0.0;
            QVERIFY(near(got.l1.pseudorange, l1, 0.01 + 1e-6));
            const auto phase =
                    want.l1.phaseRange ? std::optional(*want.l1.phaseRange - shift) : std::nullopt;
            QVERIFY(near(got.l1.phaseRange, phase, 0.0103));
            QVERIFY(near(got.l1.cnr, o.extended() ? want.l1.cnr : std::nullopt, 0.125));
            QCOMPARE(got.l2.has_value(), o.hasL2());
            if (!o.hasL2()) continue;
            QCOMPARE(got.l2->code, want.l2->code);
            QCOMPARE(got.l2->lockTime, want.l2->lockTime);
            const auto l2 = want.l2->pseudorange ? std::optional(*want.l2->pseudorange - shift)
                                                 : std::nullopt;
            QVERIFY(near(got.l2->pseudorange, l2, 0.0201));
            QVERIFY(near(got.l2->phaseRange, *want.l2->phaseRange - shift, 0.0103));
            QVERIFY(near(got.l2->cnr, o.extended() ? want.l2->cnr : std::nullopt, 0.125));
        }
        // Decoded values encode to the same frame.
        QCOMPARE(encodeLegacy(*d), encodeLegacy(o));
    }

    // GPS 1004, one satellite, fields written one by one; expected values worked out from the
    // DF resolutions, not from the decoder.
    void gps1004FieldsAsDefined() {
        gnss::rtcm::BitWriter w;
        w.u(1004, 12).u(2003, 12).u(345600000, 30).u(1, 1).u(1, 5).u(1, 1).u(5, 3);
        w.u(12, 6).u(0, 1).u(1234567, 24).s(-1000, 20).u(100, 7).u(73, 8).u(180, 8);
        w.u(1, 2).s(250, 14).s(12345, 20).u(99, 7).u(160, 8);
        const RtcmMessage m = decodeMessage(w.bytes());
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.length, std::size_t(24)); // 64 + 125 bits = 189 → 24 bytes
        const LegacyObservables *d = legacyOf(m);
        QVERIFY(d);
        QCOMPARE(d->station, 2003u);
        QCOMPARE(d->epochMs, 345600000u); // Wednesday 00:00 GPS time
        QVERIFY(d->synchronous);
        QVERIFY(d->smoothing);
        QCOMPARE(d->smoothingInterval, 5u);
        QCOMPARE(d->satellites.size(), std::size_t(1));
        const LegacySatellite &s = d->satellites[0];
        QCOMPARE(s.id, 12u);
        QCOMPARE(s.ambiguity, std::optional<unsigned>(73));
        QVERIFY(!s.frequencyChannel);
        // DF011 1234567 × 0.02 = 24691.34; DF014 73 × 299792.458 = 21884849.434.
        QVERIFY(near(s.l1.pseudorange, 21909540.774, 1e-6));
        // DF012 −1000 × 0.0005 = −0.5.
        QVERIFY(near(s.l1.phaseRange, 21909540.274, 1e-6));
        QCOMPARE(s.l1.lockTime, 100u);
        QCOMPARE(s.l1.cnr, std::optional(45.0)); // DF015 180 × 0.25
        QVERIFY(s.l2);
        QCOMPARE(s.l2->code, 1u);
        QCOMPARE(legacySignalName(System::Gps, 2, s.l2->code), std::string_view("2P"));
        QVERIFY(near(s.l2->pseudorange, 21909545.774, 1e-6)); // DF017 250 × 0.02 = 5.00
        QVERIFY(near(s.l2->phaseRange, 21909546.9465, 1e-6)); // DF018 12345 × 0.0005 = 6.1725
        QCOMPARE(s.l2->lockTime, 99u);
        QCOMPARE(s.l2->cnr, std::optional(40.0)); // DF020 160 × 0.25
    }

    // GLONASS 1012, one satellite: P code on L1, L2 pseudorange invalid, no L2 CNR.
    void glonass1012FieldsAsDefined() {
        gnss::rtcm::BitWriter w;
        w.u(1012, 12).u(77, 12).u(43200000, 27).u(0, 1).u(1, 5).u(0, 1).u(0, 3);
        w.u(7, 6).u(1, 1).u(10, 5).u(20000000, 25).s(40000, 20).u(127, 7).u(35, 7).u(200, 8);
        w.u(0, 2).s(-8192, 14).s(-2000, 20).u(5, 7).u(0, 8);
        const RtcmMessage m = decodeMessage(w.bytes());
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.length, std::size_t(24)); // 61 + 130 bits = 191 → 24 bytes
        const LegacyObservables *d = legacyOf(m);
        QVERIFY(d);
        QCOMPARE(d->system(), System::Glonass);
        QCOMPARE(d->epochMs, 43200000u); // noon, GLONASS time of day
        QVERIFY(!d->synchronous);
        QCOMPARE(d->satellites.size(), std::size_t(1));
        const LegacySatellite &s = d->satellites[0];
        QCOMPARE(s.id, 7u);
        QCOMPARE(s.frequencyChannel, std::optional<int>(3)); // DF040 10 − 7
        QCOMPARE(s.l1.code, 1u);
        QCOMPARE(legacySignalName(System::Glonass, 1, s.l1.code), std::string_view("1P"));
        // DF041 20000000 × 0.02 = 400000.00; DF044 35 × 599584.916 = 20985472.06.
        QVERIFY(near(s.l1.pseudorange, 21385472.06, 1e-6));
        QVERIFY(near(s.l1.phaseRange, 21385492.06, 1e-6)); // DF042 40000 × 0.0005 = 20.0
        QCOMPARE(s.l1.lockTime, 127u);
        QCOMPARE(s.l1.cnr, std::optional(50.0)); // DF045 200 × 0.25
        QVERIFY(s.l2);
        QCOMPARE(legacySignalName(System::Glonass, 2, s.l2->code), std::string_view("2C"));
        QVERIFY(!s.l2->pseudorange);                        // DF047 0x2000: invalid
        QVERIFY(near(s.l2->phaseRange, 21385471.06, 1e-6)); // DF048 −2000 × 0.0005 = −1.0
        QCOMPARE(s.l2->lockTime, 5u);
        QVERIFY(!s.l2->cnr); // DF050 0: not computed
    }

    void invalidPhaseIsAbsent() {
        gnss::rtcm::BitWriter w;
        w.u(1001, 12).u(1, 12).u(0, 30).u(0, 1).u(1, 5).u(0, 1).u(0, 3);
        w.u(5, 6).u(0, 1).u(100, 24).s(-524288, 20).u(0, 7);
        const RtcmMessage m = decodeMessage(w.bytes());
        const LegacyObservables *d = legacyOf(m);
        QVERIFY(d);
        QVERIFY(near(d->satellites.at(0).l1.pseudorange, 2.0, 1e-9));
        QVERIFY(!d->satellites.at(0).l1.phaseRange);
        QVERIFY(!d->satellites.at(0).l1.cnr);
        QVERIFY(!d->satellites.at(0).l2);
    }

    // Every payload shorter than the message is refused with an error and no body, keeping the
    // station once it is there; a count of satellites the payload cannot hold likewise.
    void shortPayloadsAreRefused_data() { everyNumberRoundTripsWithinResolution_data(); }
    void shortPayloadsAreRefused() {
        QFETCH(uint, number);
        const std::vector<std::uint8_t> whole = legacyPayload(sample(number));
        for (std::size_t n = 0; n < whole.size(); ++n) {
            const std::vector<std::uint8_t> cut(whole.begin(), whole.begin() + long(n));
            const RtcmMessage m = decodeMessage(cut);
            QVERIFY2(!m.error.empty(), qPrintable(QString::number(n)));
            QVERIFY(std::holds_alternative<std::monostate>(m.body));
            if (n >= 3) QCOMPARE(m.station, std::optional<unsigned>(number));
        }
        std::vector<std::uint8_t> more = whole;
        const std::size_t count = number >= 1009 ? 52 : 55; // DF035 / DF006: 5 bits from here
        for (std::size_t bit = count; bit < count + 5; ++bit)
            more[bit / 8] |= std::uint8_t(0x80 >> bit % 8); // 31 satellites
        QVERIFY(!decodeMessage(more).error.empty());
    }

    void jsonListsSatellitesSignalsAndObservations() {
        const QJsonObject o = jsonObjectOf(decodeFrame(encodeLegacy(sample(1012))));
        QCOMPARE(o["type"].toInt(), 1012);
        QCOMPARE(o["system"].toString(), QString("GLONASS"));
        QCOMPARE(o["tod_ms"].toInteger(), 86399000);
        QCOMPARE(o["satellites"].toArray(), (QJsonArray{24, 17, 10}));
        QCOMPARE(o["signals"].toArray(),
                 (QJsonArray{QJsonObject{{"name", "1C"}}, QJsonObject{{"name", "1P"}},
                             QJsonObject{{"name", "2C"}}, QJsonObject{{"name", "2P"}}}));
        const QJsonArray obs = o["observations"].toArray();
        QCOMPARE(obs.size(), 3);
        const QJsonObject last = obs[2].toObject();
        QCOMPARE(last["frequency_channel"].toInt(), 3);
        QVERIFY(!last["l1"].toObject().contains("phase_range"));
        QVERIFY(!last["l2"].toObject().contains("pseudorange"));
        QCOMPARE(last["l2"].toObject()["cnr"].toDouble(), 32.0);
        const QJsonObject gps = jsonObjectOf(decodeFrame(encodeLegacy(sample(1001))));
        QCOMPARE(gps["tow_ms"].toInteger(), 604799000);
        QVERIFY(!gps["observations"].toArray()[0].toObject().contains("l2"));
    }

    void legacyAndMsmShareTheObservedView() {
        const auto legacy = observedSignals(decodeFrame(encodeLegacy(sample(1004))));
        QVERIFY(legacy);
        QCOMPARE(legacy->system, System::Gps);
        QCOMPARE(legacy->epochMs, 604799000u);
        QCOMPARE(legacy->satellites, (std::vector<unsigned>{2, 12, 22}));
        QCOMPARE(legacy->signalNames,
                 (std::vector<std::string_view>{"1C", "1P", "2X", "2P", "2D"}));
        MsmHeader h = msmHeader(System::Glonass, 4, satMask({3, 9}), sigMask({2, 8}));
        h.gloDayOfWeek = 2;
        h.epochMs = 1000;
        const auto msm = observedSignals(decodeFrame(encodeMsm(h)));
        QVERIFY(msm);
        QCOMPARE(msm->system, System::Glonass);
        QCOMPARE(msm->gloDayOfWeek, std::optional<unsigned>(2));
        QCOMPARE(msm->satellites, (std::vector<unsigned>{3, 9}));
        QCOMPARE(msm->signalNames, (std::vector<std::string_view>{"1C", "2C"}));
        QVERIFY(!observedSignals(decodeFrame(encodeGlonassBiases({}))));
    }
};

QTEST_GUILESS_MAIN(TstRtcmLegacy)
#include "tst_rtcm_legacy.moc"
