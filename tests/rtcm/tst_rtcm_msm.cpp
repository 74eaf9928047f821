// MSM1..MSM7 headers of every system: round trips through the encoder, satellite and signal lists
// from the masks, signal names, and bodies that do not match their masks.
#include "rtcm/bit_reader.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"

#include <QTest>

#include <bit>

using namespace gnss::rtcm;
using namespace rtcm_test;

Q_DECLARE_METATYPE(System)

namespace {

// The satellites and signals of a plausible header for each system.
struct Masks {
    std::uint64_t satellite;
    std::uint32_t signal;
};

Masks masksFor(System s) {
    switch (s) {
    case System::Gps: return {satMask({2, 5, 13, 32}), sigMask({2, 15, 22})};
    case System::Glonass: return {satMask({1, 8, 24}), sigMask({2, 8})};
    case System::Galileo: return {satMask({4, 36}), sigMask({2, 14, 18, 22})};
    case System::Sbas: return {satMask({4, 7}), sigMask({2})};
    case System::Qzss: return {satMask({1, 2, 3, 7}), sigMask({2, 16})};
    case System::BeiDou: return {satMask({6, 19, 46, 63}), sigMask({2, 8, 14, 22})};
    case System::NavIC: return {satMask({1, 9}), sigMask({8, 22})};
    }
    return {};
}

// A plausible header for each system: its own satellites and signals.
MsmHeader headerFor(System s, unsigned type) {
    const Masks masks = masksFor(s);
    MsmHeader h = msmHeader(s, type, masks.satellite, masks.signal);
    h.station = 100 * static_cast<unsigned>(s) + type;
    if (s == System::Glonass) h.gloDayOfWeek = 3;
    h.epochMs = h.gloDayOfWeek ? 86399999u - type : 604799000u + type;
    h.clockSteering = type % 4;
    h.externalClock = (type + 1) % 4;
    h.smoothingInterval = 7 - type;
    return h;
}

const MsmHeader *msmOf(const RtcmMessage &m) {
    return std::get_if<MsmHeader>(&m.body);
}

} // namespace

class TstRtcmMsm : public QObject {
    Q_OBJECT
private slots:
    void everyMsmHeaderRoundTrips_data() {
        QTest::addColumn<System>("system");
        QTest::addColumn<uint>("type");
        for (int s = 0; s <= static_cast<int>(System::NavIC); ++s)
            for (unsigned t = 1; t <= 7; ++t) {
                const auto sys = static_cast<System>(s);
                const unsigned number = 1070 + 10 * unsigned(s) + t;
                QTest::addRow("%u %s MSM%u", number, std::string(systemName(sys)).c_str(), t)
                        << sys << t;
            }
    }
    void everyMsmHeaderRoundTrips() {
        QFETCH(System, system);
        QFETCH(uint, type);
        const MsmHeader h = headerFor(system, type);
        const std::string f = encodeMsm(h);
        const RtcmMessage m = decodeFrame(f);
        QCOMPARE(m.number, 1070 + 10 * static_cast<unsigned>(system) + type);
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.station, std::optional<unsigned>(h.station));
        const MsmHeader *d = msmOf(m);
        QVERIFY(d);
        QCOMPARE(d->system, system);
        QCOMPARE(d->msmType, type);
        QCOMPARE(d->station, h.station);
        QCOMPARE(d->epochMs, h.epochMs);
        QCOMPARE(d->gloDayOfWeek, h.gloDayOfWeek);
        QCOMPARE(d->multipleMessage, h.multipleMessage);
        QCOMPARE(d->iods, h.iods);
        QCOMPARE(d->clockSteering, h.clockSteering);
        QCOMPARE(d->externalClock, h.externalClock);
        QCOMPARE(d->smoothing, h.smoothing);
        QCOMPARE(d->smoothingInterval, h.smoothingInterval);
        QCOMPARE(d->satelliteMask, h.satelliteMask);
        QCOMPARE(d->signalMask, h.signalMask);
        QCOMPARE(d->cellMask, h.cellMask);
        QCOMPARE(int(d->satelliteCount), std::popcount(h.satelliteMask));
        QCOMPARE(int(d->signalCount), std::popcount(h.signalMask));
        QCOMPARE(int(d->cellCount), std::popcount(h.cellMask));
        // The frame is exactly as long as header, cell mask and body need.
        const std::size_t bits = kMsmHeaderBits + d->satelliteCount * d->signalCount +
                                 msmBodyBits(type, d->satelliteCount, d->cellCount);
        QCOMPARE(m.length, (bits + 7) / 8);
    }

    void satelliteAndSignalListsFollowTheMasks() {
        MsmHeader h;
        h.system = System::Gps;
        h.msmType = 4;
        h.satelliteMask = satMask({1, 64});
        h.signalMask = sigMask({1, 32});
        h.cellMask = 0b1001;
        const RtcmMessage m = decodeFrame(encodeMsm(h));
        const MsmHeader *d = msmOf(m);
        QVERIFY(d);
        QCOMPARE(std::vector<std::uint8_t>(d->satelliteIds().begin(), d->satelliteIds().end()),
                 (std::vector<std::uint8_t>{1, 64}));
        QCOMPARE(std::vector<std::uint8_t>(d->signalIds().begin(), d->signalIds().end()),
                 (std::vector<std::uint8_t>{1, 32}));
        QCOMPARE(int(d->cellCount), 2);
    }

    void theSatelliteMaskIsReadWhereTheStandardPutsIt() {
        // Independent of the encoder's layout: GPS satellite 1 is the MSB of DF394, which starts at
        // bit 12+12+30+1+3+7+2+2+1+3 = 73 of the payload.
        MsmHeader h;
        h.system = System::Galileo;
        h.msmType = 7;
        h.satelliteMask = satMask({1});
        h.signalMask = sigMask({32});
        const auto payload = msmPayload(h);
        BitReader r(payload, 73);
        QCOMPARE(r.u(1), std::uint64_t(1));
        QCOMPARE(r.u(63), std::uint64_t(0));
        QCOMPARE(r.u(32), std::uint64_t(1));
    }

    void signalIdsHaveRinexNames_data() {
        QTest::addColumn<System>("system");
        QTest::addColumn<uint>("id");
        QTest::addColumn<QString>("name");
        QTest::newRow("GPS 2 L1 C/A") << System::Gps << 2u << "1C";
        QTest::newRow("GPS 3 L1 P") << System::Gps << 3u << "1P";
        QTest::newRow("GPS 4 L1 Z") << System::Gps << 4u << "1W";
        QTest::newRow("GPS 8 L2 C/A") << System::Gps << 8u << "2C";
        QTest::newRow("GPS 10 L2 Z") << System::Gps << 10u << "2W";
        QTest::newRow("GPS 15 L2C(M)") << System::Gps << 15u << "2S";
        QTest::newRow("GPS 16 L2C(L)") << System::Gps << 16u << "2L";
        QTest::newRow("GPS 17 L2C(M+L)") << System::Gps << 17u << "2X";
        QTest::newRow("GPS 22 L5 I") << System::Gps << 22u << "5I";
        QTest::newRow("GPS 24 L5 I+Q") << System::Gps << 24u << "5X";
        QTest::newRow("GPS 30 L1C-D") << System::Gps << 30u << "1S";
        QTest::newRow("GPS 32 L1C-D+P") << System::Gps << 32u << "1X";
        QTest::newRow("GPS 1 reserved") << System::Gps << 1u << "";
        QTest::newRow("GPS 5 reserved") << System::Gps << 5u << "";
        QTest::newRow("GLONASS 2 G1 C/A") << System::Glonass << 2u << "1C";
        QTest::newRow("GLONASS 3 G1 P") << System::Glonass << 3u << "1P";
        QTest::newRow("GLONASS 8 G2 C/A") << System::Glonass << 8u << "2C";
        QTest::newRow("GLONASS 9 G2 P") << System::Glonass << 9u << "2P";
        QTest::newRow("GLONASS 22 unknown") << System::Glonass << 22u << "";
        QTest::newRow("Galileo 2 E1 C") << System::Galileo << 2u << "1C";
        QTest::newRow("Galileo 5 E1 B+C") << System::Galileo << 5u << "1X";
        QTest::newRow("Galileo 8 E6 C") << System::Galileo << 8u << "6C";
        QTest::newRow("Galileo 14 E5b I") << System::Galileo << 14u << "7I";
        QTest::newRow("Galileo 16 E5b I+Q") << System::Galileo << 16u << "7X";
        QTest::newRow("Galileo 18 E5 AltBOC I") << System::Galileo << 18u << "8I";
        QTest::newRow("Galileo 22 E5a I") << System::Galileo << 22u << "5I";
        QTest::newRow("Galileo 24 E5a I+Q") << System::Galileo << 24u << "5X";
        QTest::newRow("SBAS 2 L1 C/A") << System::Sbas << 2u << "1C";
        QTest::newRow("SBAS 23 L5 Q") << System::Sbas << 23u << "5Q";
        QTest::newRow("QZSS 2 L1 C/A") << System::Qzss << 2u << "1C";
        QTest::newRow("QZSS 9 LEX S") << System::Qzss << 9u << "6S";
        QTest::newRow("QZSS 16 L2C(L)") << System::Qzss << 16u << "2L";
        QTest::newRow("QZSS 30 L1C-D") << System::Qzss << 30u << "1S";
        QTest::newRow("BeiDou 2 B1 I") << System::BeiDou << 2u << "2I";
        QTest::newRow("BeiDou 8 B3 I") << System::BeiDou << 8u << "6I";
        QTest::newRow("BeiDou 14 B2 I") << System::BeiDou << 14u << "7I";
        QTest::newRow("BeiDou 22 B2a D") << System::BeiDou << 22u << "5D";
        QTest::newRow("BeiDou 25 B2b D") << System::BeiDou << 25u << "7D";
        QTest::newRow("BeiDou 30 B1C D") << System::BeiDou << 30u << "1D";
        QTest::newRow("NavIC 22 L5 A") << System::NavIC << 22u << "5A";
        QTest::newRow("NavIC 8 unknown") << System::NavIC << 8u << "";
        QTest::newRow("id 0 is no id") << System::Gps << 0u << "";
        QTest::newRow("id 33 is no id") << System::Gps << 33u << "";
    }
    void signalIdsHaveRinexNames() {
        QFETCH(System, system);
        QFETCH(uint, id);
        QFETCH(QString, name);
        QCOMPARE(QString::fromStdString(std::string(msmSignalName(system, id))), name);
    }

    void sbasAndQzssSatellitesMapToTheirPrns() {
        QCOMPARE(msmPrn(System::Sbas, 1), 120u);
        QCOMPARE(msmPrn(System::Sbas, 39), 158u);
        QCOMPARE(msmPrn(System::Qzss, 1), 193u);
        QCOMPARE(msmPrn(System::Gps, 32), 32u);
        QCOMPARE(msmPrn(System::Glonass, 24), 24u);
    }

    void msmNumbersAreRecognised_data() {
        QTest::addColumn<uint>("number");
        QTest::addColumn<bool>("msm");
        for (const uint n : {1071u, 1077u, 1081u, 1097u, 1101u, 1117u, 1121u, 1137u})
            QTest::addRow("%u is an MSM", n) << n << true;
        for (const uint n : {1070u, 1078u, 1079u, 1080u, 1138u, 1141u, 1004u, 4095u})
            QTest::addRow("%u is not", n) << n << false;
    }
    void msmNumbersAreRecognised() {
        QFETCH(uint, number);
        QFETCH(bool, msm);
        QCOMPARE(isMsm(number), msm);
    }

    void aHeaderWithMoreThan64CellsIsAnError() {
        MsmHeader h;
        h.system = System::Gps;
        h.msmType = 7;
        h.station = 5;
        h.satelliteMask = satMask({1, 2, 3, 4, 5, 6, 7, 8, 9});
        h.signalMask = sigMask({2, 3, 4, 8, 9, 10, 15, 16}); // 9 × 8 = 72 cells
        const RtcmMessage m = decodeFrame(encodeMsm(h));
        QCOMPARE(m.number, 1077u);
        QCOMPARE(m.station, std::optional<unsigned>(5));
        QVERIFY(!m.error.empty());
        QVERIFY(!msmOf(m));
    }

    void exactly64CellsIsFine() {
        MsmHeader h = headerFor(System::Gps, 1);
        h.satelliteMask = satMask({1, 2, 3, 4, 5, 6, 7, 8});
        h.signalMask = sigMask({2, 3, 4, 8, 9, 10, 15, 16});
        h.cellMask = ~std::uint64_t(0);
        const RtcmMessage m = decodeFrame(encodeMsm(h));
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(int(msmOf(m)->cellCount), 64);
    }

    void aBodyShorterThanItsMasksSayIsAnError() {
        for (unsigned type = 1; type <= 7; ++type) {
            const auto payload = msmPayload(headerFor(System::BeiDou, type));
            QVERIFY(decodeMessage(payload).error.empty());
            for (std::size_t n = 0; n < payload.size(); ++n) {
                const RtcmMessage m = decodeMessage(std::span(payload).first(n));
                QVERIFY(!m.error.empty());
                QVERIFY(!msmOf(m));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TstRtcmMsm)
#include "tst_rtcm_msm.moc"
