// Every Nemerix encoder, byte for byte (checksums computed independently of the library), the
// refusals (nothing built, the message names the parameter and the accepted range), the
// renamed prefix, and every encoded command decoding back to what was asked.
#include "decode_helper.h"
#include "nemerix/nemerix_commands.h"

#include <QTest>

#include <functional>
#include <vector>

using namespace gnss::nemerix;
using gnss::EncodeResult;

namespace {

struct Case {
    const char *name;
    std::function<EncodeResult()> encode;
    const char *expected; // a sentence, or for refusals the text the error must contain
};

std::vector<RateItem> rates(std::initializer_list<RateItem> l) {
    return l;
}
std::vector<FixMaskItem> masks(std::initializer_list<FixMaskItem> l) {
    return l;
}
std::vector<std::string> ids(std::initializer_list<std::string> l) {
    return l;
}

// A row's encoder: encodeFixSettings of these masks (likewise the rates and the sequence).
std::function<EncodeResult()> fixSettings(std::initializer_list<FixMaskItem> l) {
    return [v = masks(l)] { return encodeFixSettings(v); };
}
std::function<EncodeResult()> nemerixRates(std::initializer_list<RateItem> l) {
    return [v = rates(l)] { return encodeNemerixRates(v); };
}
std::function<EncodeResult()> nmeaRates(std::initializer_list<RateItem> l) {
    return [v = rates(l)] { return encodeNmeaRates(v); };
}
std::function<EncodeResult()> nmeaSequence(std::initializer_list<std::string> l) {
    return [v = ids(l)] { return encodeNmeaSequence(v); };
}

std::function<EncodeResult()> datum(DatumParams d) {
    return [d] { return encodeDatum(d); };
}

EncodeResult encodeParams(const NavInitParams &p) {
    return encodeNavInit(p);
}
EncodeResult encodeParams(const LlaInitParams &p) {
    return encodeLlaInit(p);
}

// A row's encoder: the parameters as `fill` leaves them, through their encoder.
template <class P> std::function<EncodeResult()> filled(void (*fill)(P &)) {
    return [fill] {
        P p;
        fill(p);
        return encodeParams(p);
    };
}

const std::vector<Case> &encodings() {
    static const std::vector<Case> c = {
            {"PNMRX100 spec example", [] { return encodeSerialPort(0, 4800, 0); },
             "$PNMRX100,0,4800,0*48"},
            {"PNMRX100 57600 even", [] { return encodeSerialPort(0, 57600, 2); },
             "$PNMRX100,0,57600,2*72"},
            {"PNMRX100 binary 1200 odd", [] { return encodeSerialPort(1, 1200, 1); },
             "$PNMRX100,1,1200,1*47"},
            {"PNMRX101 spec example position", filled<NavInitParams>([](NavInitParams &p) {
                 p.x = -742507, p.y = -5462738, p.z = 3196706;
             }),
             "$PNMRX101,-742507,-5462738,3196706,*6F"},
            {"PNMRX101 channel count",
             filled<NavInitParams>([](NavInitParams &p) { p.channels = 16; }),
             "$PNMRX101,,,,,,,16,*6E"},
            {"PNMRX101 every field",
             [] {
                 return encodeNavInit({1, 2, 3, -250, 345600, 1234, 12});
             },
             "$PNMRX101,1,2,3,-250,345600,1234,12,*40"},
            {"PNMRX103 spec example", nmeaRates({{"GSV", 2}, {"GGA", 1}, {"ZDA", 0}}),
             "$PNMRX103,GSV,2,GGA,1,ZDA,0*04"},
            {"PNMRX103 ALL 2", nmeaRates({{"ALL", 2}}), "$PNMRX103,ALL,2*18"},
            {"PNMRX103 ALL 0", nmeaRates({{"ALL", 0}}), "$PNMRX103,ALL,0*1A"},
            {"PNMRX104 north east", filled<LlaInitParams>([](LlaInitParams &p) {
                 p.lat = 48.1173, p.lon = 11.516666666666667, p.altitude = 545;
             }),
             "$PNMRX104,4807.0380,N,01131.0000,E,545*4D"},
            {"PNMRX104 south west with channels", filled<LlaInitParams>([](LlaInitParams &p) {
                 p.lat = -(33 + 51.81 / 60), p.lon = -(151 + 12.62 / 60), p.altitude = -12;
                 p.channels = 14;
             }),
             "$PNMRX104,3351.8100,S,15112.6200,W,-12,,,,14*50"},
            {"PNMRX104 week only", filled<LlaInitParams>([](LlaInitParams &p) { p.week = 2100; }),
             "$PNMRX104,,,,,,,,2100*6F"},
            {"PNMRX106 WGS84 spec example", datum({1, 216}), "$PNMRX106,1,216,*46"},
            {"PNMRX106 user datum spec example",
             datum({0, 500, -2000, -2000, -2000, 298.257224, 6378137.0}),
             "$PNMRX106,0,500,-2000,-2000,-2000,8257224,8137000*69"},
            {"PNMRX107 300 now", nemerixRates({{"300", 1}}), "$PNMRX107,300,1*6D"},
            {"PNMRX107 301 on change", nemerixRates({{"301", 2}}), "$PNMRX107,301,2*6F"},
            {"PNMRX107 ALL", nemerixRates({{"ALL", 2}}), "$PNMRX107,ALL,2*1C"},
            {"PNMRX107 three", nemerixRates({{"302", 0}, {"303", 3}, {"304", 1}}),
             "$PNMRX107,302,0,303,3,304,1*6B"},
            {"PNMRX108 three", nmeaSequence({"GGA", "GLL", "GSA"}), "$PNMRX108,GGA,GLL,GSA*1F"},
            {"PNMRX108 all reversed",
             nmeaSequence({"ZDA", "RMC", "VTG", "GSV", "GSA", "GLL", "GGA"}),
             "$PNMRX108,ZDA,RMC,VTG,GSV,GSA,GLL,GGA*1B"},
            {"PNMRX110 mask 0 spec example", fixSettings({{0, "-2:0"}}), "$PNMRX110,0,-2:0*4C"},
            {"PNMRX110 mask 0 plus sign", fixSettings({{0, "+5:30"}}), "$PNMRX110,0,5:30*55"},
            {"PNMRX110 mask 0 minus half hour", fixSettings({{0, "-0:30"}}),
             "$PNMRX110,0,-0:30*7D"},
            {"PNMRX110 mask 1 PDOP x10", fixSettings({{1, "2.5"}}), "$PNMRX110,1,25*5F"},
            {"PNMRX110 mask 2 HDOP x10", fixSettings({{2, "10"}}), "$PNMRX110,2,100*6A"},
            {"PNMRX110 mask 3 VDOP x10", fixSettings({{3, "0"}}), "$PNMRX110,3,0*6A"},
            {"PNMRX110 mask 4 spec example", fixSettings({{4, "35"}}), "$PNMRX110,4,35*5B"},
            {"PNMRX110 mask 5", fixSettings({{5, "15"}}), "$PNMRX110,5,15*58"},
            {"PNMRX110 mask 6", fixSettings({{6, "600"}}), "$PNMRX110,6,600*69"},
            {"PNMRX110 mask 7", fixSettings({{7, "4"}}), "$PNMRX110,7,4*6A"},
            {"PNMRX110 mask 8", fixSettings({{8, "250"}}), "$PNMRX110,8,250*66"},
            {"PNMRX110 mask 9", fixSettings({{9, "1"}}), "$PNMRX110,9,1*61"},
            {"PNMRX110 mask 10", fixSettings({{10, "18000"}}), "$PNMRX110,10,18000*51"},
            {"PNMRX110 several", fixSettings({{4, "30"}, {5, "10"}, {1, "6"}}),
             "$PNMRX110,4,30,5,10,1,60*5D"},
            {"PNMRX111 no argument", [] { return encodeSoftwareReset(); }, "$PNMRX111*68"},
            {"PNMRX111 FACTORY", [] { return encodeSoftwareReset("FACTORY"); },
             "$PNMRX111,FACTORY*10"},
            {"PNMRX111 COLD", [] { return encodeSoftwareReset("COLD"); }, "$PNMRX111,COLD*40"},
            {"PNMRX111 WARM", [] { return encodeSoftwareReset("WARM"); }, "$PNMRX111,WARM*4D"},
            {"PNMRX111 HOT", [] { return encodeSoftwareReset("HOT"); }, "$PNMRX111,HOT*17"},
            {"PNMRX111 bit field", [] { return encodeSoftwareReset("131"); }, "$PNMRX111,131*77"},
            {"PNMRX112 spec example", [] { return encodePowerMode(1, 5); }, "$PNMRX112,1,5*6F"},
            {"PNMRX112 fully active", [] { return encodePowerMode(0); }, "$PNMRX112,0*77"},
            {"PNMRX112 off 10 s", [] { return encodePowerMode(1, 10); }, "$PNMRX112,1,10*5B"},
            {"PNMRX113", [] { return encodeStopCore(); }, "$PNMRX113*6A"},
            {"PNMRX600", [] { return encodeVersionQuery(); }, "$PNMRX600*6F"},
            {"PNMRX601", [] { return encodeIspMode(); }, "$PNMRX601*6E"},
            {"PNMRX603", [] { return encodeSettingsQuery(); }, "$PNMRX603*6C"},
            {"renamed PNMRX100", [] { return encodeSerialPort(0, 9600, 0, "PXYZW"); },
             "$PXYZW100,0,9600,0*4E"},
            {"renamed PNMRX110",
             [] {
                 return encodeFixSettings(masks({{4, "35"}}), "PXYZW");
             },
             "$PXYZW110,4,35*5E"},
            {"renamed PNMRX603", [] { return encodeSettingsQuery("PXYZW"); }, "$PXYZW603*69"},
            {"renamed short", [] { return encodeSettingsQuery("PX"); }, "$PX603*3D"},
    };
    return c;
}

const std::vector<Case> &refusals() {
    static const std::vector<Case> c = {
            {"baud not in table", [] { return encodeSerialPort(0, 115200, 0); }, "baud: 115200"},
            {"protocol 2", [] { return encodeSerialPort(2, 9600, 0); }, "protocol: 2"},
            {"parity 3", [] { return encodeSerialPort(0, 9600, 3); }, "parity: 3"},
            {"ECEF without z", filled<NavInitParams>([](NavInitParams &p) { p.x = 1, p.y = 2; }),
             "x, y and z"},
            {"channels 11", filled<NavInitParams>([](NavInitParams &p) { p.channels = 11; }),
             "channel count: 11 is out of range; accepted: 12..16"},
            {"PNMRX101 empty", [] { return encodeNavInit({}); }, "no parameter"},
            {"latitude 91",
             filled<LlaInitParams>([](LlaInitParams &p) { p.lat = 91, p.lon = 0, p.altitude = 0; }),
             "latitude"},
            {"LLA without altitude",
             filled<LlaInitParams>([](LlaInitParams &p) { p.lat = 1, p.lon = 2; }), "together"},
            {"rate 10", nmeaRates({{"GGA", 10}}),
             "rate of GGA: 10 is out of range; accepted: 0..9"},
            {"rate unknown id", nmeaRates({{"GNS", 1}}), "'GNS'"},
            {"mode 4", nemerixRates({{"300", 4}}), "0..3"},
            {"mode unknown message", nemerixRates({{"305", 1}}), "'305'"},
            {"sequence duplicate", nmeaSequence({"GGA", "GGA"}), "twice"},
            {"sequence unknown", nmeaSequence({"GGA", "XYZ"}), "'XYZ'"},
            {"datum 219", datum({0, 219}), "datum: 219"},
            {"user datum incomplete", datum({0, 500, 1, 2, 3}), "needs"},
            {"user datum dx", datum({0, 500, 10000, 0, 0, 298.0, 6378137.0}), "-9999..9999"},
            {"user datum flattening", datum({0, 500, 0, 0, 0, 310.0, 6378137.0}),
             "inverse flattening"},
            {"time zone 14", fixSettings({{0, "14:0"}}), "local_time_zone"},
            {"time zone no colon", fixSettings({{0, "-2"}}), "h:m"},
            {"SNR 19", fixSettings({{4, "19"}}),
             "min_snr: 19 is out of range; accepted: 20..45 dB-Hz"},
            {"PDOP 10.5", fixSettings({{1, "10.5"}}), "max_pdop"},
            {"PDOP 2.55", fixSettings({{1, "2.55"}}), "max_pdop"},
            {"nav mode 3", fixSettings({{7, "3"}}), "1 (auto)"},
            {"mask 11", fixSettings({{11, "1"}}), "0..10"},
            {"reset 256", [] { return encodeSoftwareReset("256"); }, "0..255"},
            {"reset NOW", [] { return encodeSoftwareReset("NOW"); }, "FACTORY, COLD, WARM, HOT"},
            {"power off 4", [] { return encodePowerMode(1, 4); }, "5..10"},
            {"power mode 1 no period", [] { return encodePowerMode(1); }, "required"},
            {"power mode 2", [] { return encodePowerMode(2, 5); }, "power mode: 2"},
            {"prefix lower case", [] { return encodeSettingsQuery("pxyzw"); }, "prefix"},
            {"prefix without P", [] { return encodeSettingsQuery("XYZW"); }, "prefix"},
            {"prefix with comma", [] { return encodeSettingsQuery("PX,Y"); }, "prefix"},
    };
    return c;
}

} // namespace

class TstNemerixEncoders : public QObject {
    Q_OBJECT
private slots:
    void everyEncoderIsByteExact_data();
    void everyEncoderIsByteExact();
    void outOfRangeValuesAreRefused_data();
    void outOfRangeValuesAreRefused();
    void applyPrefixRenamesAndRecomputesTheChecksum();
};

void TstNemerixEncoders::everyEncoderIsByteExact_data() {
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < encodings().size(); ++i)
        QTest::newRow(encodings()[i].name) << static_cast<int>(i);
}

void TstNemerixEncoders::everyEncoderIsByteExact() {
    QFETCH(int, index);
    const Case &c = encodings()[static_cast<std::size_t>(index)];
    const EncodeResult r = c.encode();
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(r.sentences.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(r.sentences[0]), QString(c.expected));
    // What we send, we can read: the command decodes with a good checksum.
    gnss::DecoderOptions o;
    o.dialect = "nemerix";
    o.addressAliases = {{"PXYZW", "PNMRX"}, {"PX", "PNMRX"}};
    const auto d = gnss::test::decodeOne(c.expected, o);
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.checksum, QString("ok"));
}

void TstNemerixEncoders::outOfRangeValuesAreRefused_data() {
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < refusals().size(); ++i)
        QTest::newRow(refusals()[i].name) << static_cast<int>(i);
}

void TstNemerixEncoders::outOfRangeValuesAreRefused() {
    QFETCH(int, index);
    const Case &c = refusals()[static_cast<std::size_t>(index)];
    const EncodeResult r = c.encode();
    QVERIFY(!r.ok());
    QVERIFY(r.sentences.empty());
    QVERIFY2(r.error.find(c.expected) != std::string::npos, r.error.c_str());
}

void TstNemerixEncoders::applyPrefixRenamesAndRecomputesTheChecksum() {
    QCOMPARE(QString::fromStdString(applyPrefix("$PNMRX110,4,35*5B", "PXYZW")),
             QString("$PXYZW110,4,35*5E"));
    QCOMPARE(QString::fromStdString(applyPrefix("$PNMRX603", "PXYZW")), QString("$PXYZW603*69"));
    QCOMPARE(QString::fromStdString(applyPrefix("$PNMRX603*6C", "PNMRX")), QString("$PNMRX603*6C"));
    // Not a Nemerix sentence: unchanged. Invalid prefix: empty.
    QCOMPARE(QString::fromStdString(applyPrefix("$GPGGA,1*00", "PXYZW")), QString("$GPGGA,1*00"));
    QVERIFY(applyPrefix("$PNMRX603*6C", "bad").empty());
    QVERIFY(checkPrefix("PNMRX").empty());
    QVERIFY(!checkPrefix("P").empty());
    QVERIFY(!checkPrefix("PABCDEFGHI").empty());
}

QTEST_APPLESS_MAIN(TstNemerixEncoders)
#include "tst_nemerix_encoders.moc"
