// 1230 GLONASS code-phase biases: a hand-built payload, round trips over masks and values, the
// "not valid" value, truncations.
#include "rtcm/bit_writer.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"

#include <QTest>

using namespace gnss::rtcm;
using namespace rtcm_test;

Q_DECLARE_METATYPE(GlonassBiases)

class TstRtcmBiases : public QObject {
    Q_OBJECT
private slots:
    void aHandBuiltPayloadDecodes() {
        // 1230, station 1, aligned, reserved 000, mask 1001 (L1 C/A and L2 P), +51 and −25 in
        // 0.02 m units: 1.02 m and −0.50 m.
        BitWriter w;
        w.u(1230, 12).u(1, 12).u(1, 1).u(0, 3).u(0b1001, 4).s(51, 16).s(-25, 16);
        const RtcmMessage m = decodeMessage(w.bytes());
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.number, 1230u);
        QCOMPARE(m.station, std::optional<unsigned>(1));
        const auto *b = std::get_if<GlonassBiases>(&m.body);
        QVERIFY(b);
        QVERIFY(b->aligned);
        QCOMPARE(b->mask, 0b1001u);
        QCOMPARE(b->present, (std::array<bool, 4>{true, false, false, true}));
        QCOMPARE(b->biases[0], std::optional<double>(1.02));
        QCOMPARE(b->biases[1], std::optional<double>());
        QCOMPARE(b->biases[3], std::optional<double>(-0.5));
    }

    void biasesRoundTrip_data() {
        QTest::addColumn<GlonassBiases>("biases");
        QTest::addColumn<int>("length");
        GlonassBiases b;
        b.station = 2003;
        QTest::newRow("no signals") << b << 4;
        b.present = {true, false, false, false};
        b.biases[0] = 0.0;
        QTest::newRow("L1 C/A only, zero") << b << 6;
        b.aligned = true;
        b.present = {true, true, true, true};
        b.biases = {1.02, -0.5, 655.34, -655.34};
        QTest::newRow("all four, extremes") << b << 12;
        b.biases = {std::nullopt, 3.0, std::nullopt, -3.0};
        QTest::newRow("all four, two not valid") << b << 12;
        b.present = {false, true, false, true};
        b.biases = {std::nullopt, 0.02, std::nullopt, -0.02};
        QTest::newRow("P codes only") << b << 8;
    }
    void biasesRoundTrip() {
        QFETCH(GlonassBiases, biases);
        QFETCH(int, length);
        const RtcmMessage m = decodeFrame(encodeGlonassBiases(biases));
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.length, std::size_t(length));
        QCOMPARE(m.station, std::optional<unsigned>(biases.station));
        const auto *b = std::get_if<GlonassBiases>(&m.body);
        QVERIFY(b);
        QCOMPARE(b->aligned, biases.aligned);
        QCOMPARE(b->present, biases.present);
        for (std::size_t i = 0; i < 4; ++i)
            if (biases.present[i]) QCOMPARE(b->biases[i], biases.biases[i]);
    }

    void everyTruncationIsAnErrorNotACrash() {
        GlonassBiases b;
        b.present = {true, true, true, true};
        b.biases = {1.0, 2.0, 3.0, 4.0};
        const auto payload = glonassBiasesPayload(b);
        for (std::size_t n = 0; n < payload.size(); ++n) {
            const RtcmMessage m = decodeMessage(std::span(payload).first(n));
            QVERIFY(!m.error.empty());
            QVERIFY(!std::get_if<GlonassBiases>(&m.body));
        }
    }
};

QTEST_GUILESS_MAIN(TstRtcmBiases)
#include "tst_rtcm_biases.moc"
