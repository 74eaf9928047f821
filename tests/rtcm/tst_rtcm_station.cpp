// Reference station messages 1005/1006 (ARP) and 1007/1008/1033 (antenna and receiver): the
// published example, round trips through the encoder, and every truncation.
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"

#include <QTest>

#include <cmath>

using namespace gnss::rtcm;
using namespace rtcm_test;

Q_DECLARE_METATYPE(StationArp)
Q_DECLARE_METATYPE(AntennaInfo)

namespace {

// RTCM 10403, example of message 1005. Checked by hand as well as by this decoder: payload bits
// 0-11 = 0x3ED = 1005, 12-23 = 0x7D3 = 2003, ITRF year 0, GPS 1, GLONASS 0, Galileo 0,
// reference-station indicator 0, then X = 11141045999, Y = -48507297108, Z = 39755214643 in
// 0.0001 m; the CRC-24Q of header and payload is 0x360B98, the last three bytes.
const std::string kExample1005 =
        fromHex("D3 00 13 3E D7 D3 02 02 98 0E DE EF 34 B4 BD 62 AC 09 41 98 6F 33 36 0B 98");

const StationArp &decodedArp(const RtcmMessage &m) {
    static const StationArp none;
    const auto *a = std::get_if<StationArp>(&m.body);
    return a ? *a : none;
}

} // namespace

class TstRtcmStation : public QObject {
    Q_OBJECT
private slots:
    void thePublished1005ExampleDecodes() {
        const RtcmMessage m = decodeFrame(kExample1005);
        QCOMPARE(m.number, 1005u);
        QCOMPARE(m.length, std::size_t(19));
        QCOMPARE(m.station, std::optional<unsigned>(2003));
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        const auto *a = std::get_if<StationArp>(&m.body);
        QVERIFY(a);
        QCOMPARE(a->station, 2003u);
        QCOMPARE(a->itrfYear, 0u);
        QVERIFY(a->gps);
        QVERIFY(!a->glonass);
        QVERIFY(!a->galileo);
        QVERIFY(!a->nonPhysical);
        QVERIFY(!a->singleReceiverOscillator);
        QCOMPARE(a->quarterCycle, 0u);
        QCOMPARE(a->x, 1114104.5999);
        QCOMPARE(a->y, -4850729.7108);
        QCOMPARE(a->z, 3975521.4643);
        QVERIFY(!a->antennaHeight);
        // Near Washington, D.C. (values from tst_rtcm_geodetic's 50-digit reference).
        QVERIFY(a->position);
        QVERIFY(std::fabs(a->position->latDeg - 38.804759430425068) < 1e-9);
        QVERIFY(std::fabs(a->position->lonDeg - -77.064773599803476) < 1e-9);
        QVERIFY(std::fabs(a->position->height - 114.56113815521872) < 1e-3);
    }

    void reEncodingThePublishedExampleGivesItsBytesBack() {
        const RtcmMessage m = decodeFrame(kExample1005);
        QCOMPARE(encodeStationArp(decodedArp(m)), kExample1005);
    }

    void stationArpRoundTrips_data() {
        QTest::addColumn<StationArp>("arp");
        StationArp a;
        a.station = 0;
        a.x = a.y = a.z = 0;
        QTest::newRow("1005 all zero (no position)") << a;
        a = {};
        a.station = 4095;
        a.itrfYear = 63;
        a.gps = a.glonass = a.galileo = a.nonPhysical = a.singleReceiverOscillator = true;
        a.quarterCycle = 3;
        a.x = 13743895.3471; // largest 38-bit value, 0.0001 m
        a.y = -13743895.3472;
        a.z = -0.0001;
        QTest::newRow("1005 every field at its limit") << a;
        a = {};
        a.station = 17;
        a.glonass = true;
        a.x = 2849878.1521;
        a.y = 2195934.8381;
        a.z = 5249094.9248;
        a.antennaHeight = 1.5432;
        QTest::newRow("1006 Moscow, 1.5432 m antenna") << a;
        a.antennaHeight = 6.5535;
        QTest::newRow("1006 highest antenna") << a;
        a.antennaHeight = 0.0;
        QTest::newRow("1006 zero antenna height") << a;
    }
    void stationArpRoundTrips() {
        QFETCH(StationArp, arp);
        const std::string f = encodeStationArp(arp);
        QCOMPARE(f.size(), std::size_t(arp.antennaHeight ? 21 + 6 : 19 + 6));
        const RtcmMessage m = decodeFrame(f);
        QCOMPARE(m.number, arp.antennaHeight ? 1006u : 1005u);
        QVERIFY(m.error.empty());
        const StationArp &b = decodedArp(m);
        QCOMPARE(m.station, std::optional<unsigned>(arp.station));
        QCOMPARE(b.station, arp.station);
        QCOMPARE(b.itrfYear, arp.itrfYear);
        QCOMPARE(b.gps, arp.gps);
        QCOMPARE(b.glonass, arp.glonass);
        QCOMPARE(b.galileo, arp.galileo);
        QCOMPARE(b.nonPhysical, arp.nonPhysical);
        QCOMPARE(b.singleReceiverOscillator, arp.singleReceiverOscillator);
        QCOMPARE(b.quarterCycle, arp.quarterCycle);
        QCOMPARE(b.x, arp.x);
        QCOMPARE(b.y, arp.y);
        QCOMPARE(b.z, arp.z);
        QCOMPARE(b.antennaHeight, arp.antennaHeight);
        QCOMPARE(b.position.has_value(), arp.x != 0 || arp.y != 0 || arp.z != 0);
    }

    void antennaInfoRoundTrips_data() {
        QTest::addColumn<uint>("number");
        QTest::addColumn<AntennaInfo>("info");
        AntennaInfo a;
        a.station = 1;
        QTest::newRow("1007 empty descriptor") << 1007u << a;
        a.antennaDescriptor = "TRM57971.00     NONE";
        a.setupId = 3;
        QTest::newRow("1007 with radome field") << 1007u << a;
        a.antennaSerial = "1441031520";
        QTest::newRow("1008") << 1008u << a;
        a.antennaSerial = "";
        QTest::newRow("1008 empty serial") << 1008u << a;
        a.station = 4095;
        a.antennaDescriptor = std::string(31, 'A');
        a.antennaSerial = std::string(31, '9');
        a.receiverType = "SEPT POLARX5";
        a.firmware = "5.4.0";
        a.receiverSerial = "3054321";
        QTest::newRow("1033 full") << 1033u << a;
        a.receiverType = "";
        a.firmware = "v\xE9 1"; // a Latin-1 byte passes as it is
        a.receiverSerial = "";
        QTest::newRow("1033 some empty") << 1033u << a;
    }
    void antennaInfoRoundTrips() {
        QFETCH(uint, number);
        QFETCH(AntennaInfo, info);
        const RtcmMessage m = decodeFrame(encodeAntennaInfo(number, info));
        QCOMPARE(m.number, number);
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QCOMPARE(m.station, std::optional<unsigned>(info.station));
        const auto *b = std::get_if<AntennaInfo>(&m.body);
        QVERIFY(b);
        QCOMPARE(b->antennaDescriptor, info.antennaDescriptor);
        QCOMPARE(b->setupId, info.setupId);
        QCOMPARE(b->antennaSerial.has_value(), number != 1007);
        if (number != 1007) QCOMPARE(*b->antennaSerial, info.antennaSerial.value_or(""));
        QCOMPARE(b->receiverType.has_value(), number == 1033);
        if (number == 1033) {
            QCOMPARE(*b->receiverType, *info.receiverType);
            QCOMPARE(*b->firmware, *info.firmware);
            QCOMPARE(*b->receiverSerial, *info.receiverSerial);
        }
    }

    void everyTruncationIsAnErrorNotACrash() {
        AntennaInfo info;
        info.antennaDescriptor = "ANT";
        info.antennaSerial = "SN";
        info.receiverType = "RX";
        info.firmware = "FW";
        info.receiverSerial = "RSN";
        StationArp arp;
        arp.antennaHeight = 1.0;
        for (const auto &payload :
             {stationArpPayload({}), stationArpPayload(arp), antennaInfoPayload(1007, info),
              antennaInfoPayload(1008, info), antennaInfoPayload(1033, info)}) {
            QVERIFY(decodeMessage(payload).error.empty());
            for (std::size_t n = 0; n < payload.size(); ++n) {
                const RtcmMessage m = decodeMessage(std::span(payload).first(n));
                QVERIFY(!m.error.empty());
                QVERIFY(std::holds_alternative<std::monostate>(m.body));
                QCOMPARE(m.length, n);
                if (n >= 2) QCOMPARE(m.number, unsigned(payload[0] << 4 | payload[1] >> 4));
                QCOMPARE(m.station.has_value(), n >= 3);
            }
        }
    }

    void aStringCountBeyondThePayloadIsAnError() {
        // 1007 claiming a 200-character descriptor in a 6-byte payload.
        const std::vector<std::uint8_t> p = {0x3E, 0xF0, 0x01, 0xC8, 'A', 'B'};
        const RtcmMessage m = decodeMessage(p);
        QCOMPARE(m.number, 1007u);
        QCOMPARE(m.station, std::optional<unsigned>(1));
        QVERIFY(!m.error.empty());
    }
};

QTEST_GUILESS_MAIN(TstRtcmStation)
#include "tst_rtcm_station.moc"
