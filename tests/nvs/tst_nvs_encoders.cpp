// Every NVS encoder: byte-exact with the spec's examples where it prints them, correct checksums
// everywhere, decode(encode(x)) == x, and out-of-range values refused with a message naming the
// parameter and the accepted range (nothing built).
#include "builtin/dialects.h"
#include "core/sentence.h"
#include "core/stream_decoder.h"
#include "decode_helper.h"
#include "nvs/nvs_encoders.h"

#include <QTest>

#include <functional>

using namespace gnss;
using namespace gnss::nvs;
using gnss::test::decodeWith;

namespace {

QString one(const EncodeResult &r) {
    if (!r.ok()) return "error: " + QString::fromStdString(r.error);
    if (r.sentences.size() != 1) return "sentences: " + QString::number(r.sentences.size());
    return QString::fromStdString(r.sentences.front());
}

template <class T> const T &as(const Message &m) {
    const T *t = message_cast<T>(m);
    if (!t) qFatal("unexpected message type %s", std::string(m.type->name).c_str());
    return *t;
}

} // namespace

class TstNvsEncoders : public QObject {
    Q_OBJECT
private slots:
    void encodersMatchTheSpecExamplesByteForByte_data();
    void encodersMatchTheSpecExamplesByteForByte();
    void everyEncodedSentenceHasACorrectChecksum_data();
    void everyEncodedSentenceHasACorrectChecksum();
    void rtkSetAndQueryRoundTrip();
    void rtkBaseBlhBothFormsRoundTrip();
    void rtkEveryTable4ParameterQueries();
    void rzbListRoundTrips();
    void ppsEmptyFieldsStayEmpty();
    void nmeRzaRstCfgRoundTrip();
    void idlSubcommandsRoundTrip();
    void outOfRangeValuesAreRefusedNamingParameterAndRange_data();
    void outOfRangeValuesAreRefusedNamingParameterAndRange();
};

void TstNvsEncoders::encodersMatchTheSpecExamplesByteForByte_data() {
    QTest::addColumn<QString>("encoded");
    QTest::addColumn<QString>("spec");
    const RzbEntry tst[] = {{"PNVGTST", 10}};
    QTest::newRow("4.1 version request") << one(encodeVersionRequest()) << "$PNVGVER*4E";
    QTest::newRow("4.4 RZA") << one(encodeRza(1, 115200, 1)) << "$PNVGRZA,1,115200,1*6D";
    QTest::newRow("4.5 RZB clear current") << one(encodeRzb(std::nullopt, {})) << "$PNVGRZB*45";
    QTest::newRow("4.5 RZB clear UART2") << one(encodeRzb(2, {})) << "$PNVGRZB,PORT,2*6E";
    QTest::newRow("4.7 Q TST") << one(encodeQuery("GP", "PNVGTST")) << "$GPGPQ,PNVGTST*21";
    QTest::newRow("4.7 RZB TST") << one(encodeRzb(std::nullopt, tst)) << "$PNVGRZB,PNVGTST,10*18";
    QTest::newRow("4.9 PPS") << one(encodePps({'P', 'S', 'U', 1, 1000, 'D', 0}))
                             << "$PNVGPPS,P,S,U,1,1000,D,0*62";
    const RtkSet base[] = {{"MODE", "1"}, {"BASEXYZ", "4268995.2112,721584.9731,4668481.3737"}};
    QTest::newRow("4.14 RTK base + XYZ")
            << one(encodeRtk(base))
            << "$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D";
    const RtkSet blh[] = {{"BASEBLH", "0.8263954319,0.1674465031,467.7040"}};
    QTest::newRow("4.14 RTK BLH") << one(encodeRtk(blh))
                                  << "$PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040*04";
    const RtkSet xyz[] = {{"BASEXYZ", "4268995.2112,721584.9731,4668481.3737"}};
    QTest::newRow("4.14 RTK XYZ") << one(encodeRtk(xyz))
                                  << "$PNVGRTK,BASEXYZ,4268995.2112,721584.9731,4668481.3737*2F";
    QTest::newRow("4.15 IDL MODE") << one(encodeIdlMode(1)) << "$PNVGIDL,MODE,1*7C";
    QTest::newRow("4.15 IDL ADD") << one(encodeIdlAdd(3, 0.072)) << "$PNVGIDL,ADD,0003,0.0720*3B";
}

void TstNvsEncoders::encodersMatchTheSpecExamplesByteForByte() {
    QFETCH(QString, encoded);
    QFETCH(QString, spec);
    QCOMPARE(encoded, spec);
}

void TstNvsEncoders::everyEncodedSentenceHasACorrectChecksum_data() {
    QTest::addColumn<QString>("encoded");
    const RzbEntry list[] = {{"RMC", 1}, {"GSV", 5}};
    const std::string q[] = {"BASEXYZ"};
    QTest::newRow("Q GGA") << one(encodeQuery("EC", "GGA"));
    QTest::newRow("NME") << one(encodeNme(3, 8, 1));
    QTest::newRow("NME no talker") << one(encodeNme(2, 7));
    QTest::newRow("RST F") << one(encodeRst('F'));
    QTest::newRow("RST W") << one(encodeRst('W'));
    QTest::newRow("RZB UART1 list") << one(encodeRzb(1, list));
    QTest::newRow("CFG W") << one(encodeCfg('W'));
    QTest::newRow("CFG E") << one(encodeCfg('E'));
    QTest::newRow("CFG R") << one(encodeCfg('R'));
    QTest::newRow("PPS empty") << one(encodePps({}));
    QTest::newRow("RTK query") << one(encodeRtk({}, q));
    QTest::newRow("IDL ADD none") << one(encodeIdlAdd());
    QTest::newRow("IDL ADD id") << one(encodeIdlAdd(32));
    QTest::newRow("IDL REMOVE") << one(encodeIdlRemove(32));
    QTest::newRow("IDL CLEAR") << one(encodeIdlClear());
    QTest::newRow("IDL SHOW") << one(encodeIdlShow());
}

void TstNvsEncoders::everyEncodedSentenceHasACorrectChecksum() {
    QFETCH(QString, encoded);
    QVERIFY2(encoded.startsWith('$'), qPrintable(encoded));
    const std::string line = encoded.toStdString();
    Sentence s;
    QVERIFY(s.parse(line));
    QCOMPARE(int(s.checksum()), int(ChecksumStatus::Ok));
    QVERIFY(!encoded.contains('\r') && !encoded.contains('\n'));
}

void TstNvsEncoders::rtkSetAndQueryRoundTrip() {
    const RtkSet set[] = {{"PVTRATE", "10"}, {"SFTRS", "0.05"}, {"SYSGLO", "0"}};
    const std::string query[] = {"MODE", "INITGPSWEEK"};
    const auto r = encodeRtk(set, query);
    QVERIFY(r.ok());
    QCOMPARE(QString::fromStdString(r.sentences[0]).section('*', 0, 0),
             QString("$PNVGRTK,PVTRATE,10,SFTRS,0.05,SYSGLO,0,MODE,INITGPSWEEK"));
    decodeWith("nvs", r.sentences[0], [](const Message &m) {
        const auto &rtk = as<Rtk>(m);
        QCOMPARE(rtk.params.size(), std::size_t(5));
        QCOMPARE(rtk.find("PVTRATE")->values.at(0), std::string_view("10"));
        QCOMPARE(rtk.find("SFTRS")->values.at(0), std::string_view("0.05"));
        QCOMPARE(rtk.find("SYSGLO")->values.at(0), std::string_view("0"));
        QVERIFY(rtk.find("MODE")->values.empty());
        QVERIFY(rtk.find("INITGPSWEEK")->values.empty());
    });
}

void TstNvsEncoders::rtkBaseBlhBothFormsRoundTrip() {
    const RtkSet radians[] = {{"BASEBLH", "0.8263954319,0.1674465031,467.7040"}};
    const RtkSet nmea[] = {{"BASEBLH", "4720.5118287,N,00937.6956032,E,467.704"}};
    for (const auto &set : {std::span<const RtkSet>(radians), std::span<const RtkSet>(nmea)}) {
        const auto r = encodeRtk(set);
        QVERIFY2(r.ok(), r.error.c_str());
        decodeWith("nvs", r.sentences[0], [&](const Message &m) {
            const auto &rtk = as<Rtk>(m);
            QCOMPARE(rtk.params.size(), std::size_t(1));
            std::string joined;
            for (auto v : rtk.params[0].values)
                joined += (joined.empty() ? "" : ",") + std::string(v);
            QCOMPARE(joined, set[0].value);
        });
    }
}

void TstNvsEncoders::rtkEveryTable4ParameterQueries() {
    std::vector<std::string> names;
    for (auto n : rtkParameterNames()) names.emplace_back(n);
    QCOMPARE(names.size(), std::size_t(33));
    const auto r = encodeRtk({}, names);
    QVERIFY(r.ok());
    decodeWith("nvs", r.sentences[0], [&](const Message &m) {
        const auto &rtk = as<Rtk>(m);
        QCOMPARE(rtk.params.size(), names.size());
        for (std::size_t i = 0; i < names.size(); ++i) {
            QCOMPARE(std::string(rtk.params[i].name), names[i]);
            QVERIFY(rtk.params[i].values.empty());
        }
    });
}

void TstNvsEncoders::rzbListRoundTrips() {
    const RzbEntry list[] = {{"RMC", 1}, {"GSV", 5}, {"PNVGBSS", 10}};
    const auto r = encodeRzb(1, list);
    QCOMPARE(QString::fromStdString(r.sentences.at(0)).section('*', 0, 0),
             QString("$PNVGRZB,PORT,1,RMC,1,GSV,5,PNVGBSS,10"));
    decodeWith("nvs", r.sentences[0], [&](const Message &m) {
        const auto &rzb = as<Rzb>(m);
        QCOMPARE(rzb.port, std::optional<int>(1));
        QCOMPARE(rzb.entries.size(), std::size_t(3));
        for (std::size_t i = 0; i < 3; ++i) {
            QCOMPARE(rzb.entries[i].address, list[i].address);
            QCOMPARE(rzb.entries[i].rate, list[i].rate);
        }
    });
}

void TstNvsEncoders::ppsEmptyFieldsStayEmpty() {
    PpsSettings p;
    p.duration = 500;
    p.reference = 'N';
    const auto r = encodePps(p);
    QCOMPARE(QString::fromStdString(r.sentences.at(0)).section('*', 0, 0),
             QString("$PNVGPPS,,,N,,500,,"));
    decodeWith("nvs", r.sentences[0], [](const Message &m) {
        const auto &pps = as<Pps>(m);
        QVERIFY(!pps.type && !pps.mode && !pps.adjust && !pps.validity && !pps.cableDelay);
        QCOMPARE(pps.reference, std::optional<char>('N'));
        QCOMPARE(pps.duration, std::optional<int>(500));
    });
}

void TstNvsEncoders::nmeRzaRstCfgRoundTrip() {
    decodeWith("nvs", encodeNme(3, 8, 1).sentences.at(0), [](const Message &m) {
        const auto &n = as<Nme>(m);
        QCOMPARE(n.timeDecimals, std::optional<int>(3));
        QCOMPARE(n.positionDecimals, std::optional<int>(8));
        QCOMPARE(n.talkerMode, std::optional<int>(1));
    });
    decodeWith("nvs", encodeRza(2, 460800, 7).sentences.at(0), [](const Message &m) {
        const auto &z = as<Rza>(m);
        QCOMPARE(z.port, std::optional<int>(2));
        QCOMPARE(z.baud, std::optional<int>(460800));
        QCOMPARE(z.protocol, std::optional<int>(7));
    });
    decodeWith("nvs", encodeRst('W').sentences.at(0),
               [](const Message &m) { QCOMPARE(as<Rst>(m).type, std::optional<char>('W')); });
    decodeWith("nvs", encodeCfg('E').sentences.at(0),
               [](const Message &m) { QCOMPARE(as<Cfg>(m).action, std::string_view("E")); });
    decodeWith("nvs", encodeVersionRequest().sentences.at(0),
               [](const Message &m) { QVERIFY(as<Ver>(m).request); });
}

void TstNvsEncoders::idlSubcommandsRoundTrip() {
    decodeWith("nvs", encodeIdlMode(0).sentences.at(0), [](const Message &m) {
        QCOMPARE(int(as<Idl>(m).kind), int(IdlKind::Mode));
        QCOMPARE(as<Idl>(m).mode, std::optional<int>(0));
    });
    decodeWith("nvs", encodeIdlAdd().sentences.at(0), [](const Message &m) {
        QCOMPARE(int(as<Idl>(m).kind), int(IdlKind::Add));
        QVERIFY(!as<Idl>(m).stationId && !as<Idl>(m).icb);
    });
    decodeWith("nvs", encodeIdlAdd(4095).sentences.at(0), [](const Message &m) {
        QCOMPARE(as<Idl>(m).stationId, std::optional<int>(4095));
        QVERIFY(!as<Idl>(m).icb);
    });
    decodeWith("nvs", encodeIdlAdd(7, -0.25).sentences.at(0), [](const Message &m) {
        QCOMPARE(as<Idl>(m).stationId, std::optional<int>(7));
        QCOMPARE(as<Idl>(m).icb, std::optional<double>(-0.25));
    });
    decodeWith("nvs", encodeIdlRemove(32).sentences.at(0), [](const Message &m) {
        QCOMPARE(int(as<Idl>(m).kind), int(IdlKind::Remove));
        QCOMPARE(as<Idl>(m).stationId, std::optional<int>(32));
        QVERIFY(!as<Idl>(m).ok);
    });
    decodeWith("nvs", encodeIdlClear().sentences.at(0),
               [](const Message &m) { QCOMPARE(int(as<Idl>(m).kind), int(IdlKind::Clear)); });
    decodeWith("nvs", encodeIdlShow().sentences.at(0),
               [](const Message &m) { QCOMPARE(int(as<Idl>(m).kind), int(IdlKind::Show)); });
}

void TstNvsEncoders::outOfRangeValuesAreRefusedNamingParameterAndRange_data() {
    QTest::addColumn<QString>("error");
    QTest::addColumn<int>("sentences");
    QTest::addColumn<QString>("parameter");
    QTest::addColumn<QString>("range");
    auto row = [](const char *name, const EncodeResult &r, const char *param, const char *range) {
        QTest::newRow(name) << QString::fromStdString(r.error) << int(r.sentences.size())
                            << QString(param) << QString(range);
    };
    auto rtk = [](const char *name, const char *value) {
        const RtkSet s[] = {{name, value}};
        return encodeRtk(s);
    };
    row("RTK MODE 5", rtk("MODE", "5"), "rtk.MODE", "0, 1, 2, 3, 4");
    row("RTK PVTRATE 3", rtk("PVTRATE", "3"), "rtk.PVTRATE", "1, 2, 5, 10");
    row("RTK SYSGPS 2", rtk("SYSGPS", "2"), "rtk.SYSGPS", "0 or 1");
    row("RTK ELGPS 91", rtk("ELGPS", "91"), "rtk.ELGPS", "0..90");
    row("RTK BASEID 4096", rtk("BASEID", "4096"), "rtk.BASEID", "0..4095");
    row("RTK RTCMRATE 3", rtk("RTCMRATE", "3"), "rtk.RTCMRATE", "0, 1, 2, 5, 10");
    row("RTK SFTRS -1", rtk("SFTRS", "-1"), "rtk.SFTRS", ">= 0");
    row("RTK BASEXYZ two values", rtk("BASEXYZ", "1,2"), "rtk.BASEXYZ", "three numbers");
    row("RTK BASEBLH B 2 rad", rtk("BASEBLH", "2.0,0.1,100"), "rtk.BASEBLH", "-1.5708..1.5708");
    row("RTK unknown", rtk("FOO", "1"), "FOO", "Table 4");
    row("NME time 7", encodeNme(7, 7), "nmea.time_decimals", "0..6");
    row("NME position 10", encodeNme(2, 10), "nmea.position_decimals", "0..9");
    row("RST X", encodeRst('X'), "PNVGRST reset type", "F, W");
    row("RZA port 4", encodeRza(4, 115200, 1), "PNVGRZA port", "0..3");
    row("RZA baud 1200", encodeRza(1, 1200, 1), "baud", "4800..460800");
    row("RZA protocol 2", encodeRza(1, 115200, 2), "protocol", "0, 1, 7");
    const RzbEntry zero[] = {{"GGA", 0}};
    row("RZB rate 0", encodeRzb(1, zero), "GGA output rate", ">= 1");
    row("RZB port 9", encodeRzb(9, {}), "PNVGRZB port", "0..3");
    row("CFG X", encodeCfg('X'), "PNVGCFG action", "W, E, R");
    row("PPS duration 0", encodePps({std::nullopt, std::nullopt, std::nullopt, std::nullopt, 0}),
        "pps.duration", "1..1000");
    row("PPS type Q", encodePps({'Q'}), "pps.type", "P, A");
    row("IDL MODE 2", encodeIdlMode(2), "idl.mode", "0, 1");
    row("IDL ADD id 5000", encodeIdlAdd(5000), "PNVGIDL station ID", "0..4095");
    row("IDL ADD icb 2", encodeIdlAdd(1, 2.0), "PNVGIDL GLONASS ICB", "-1..1");
    row("IDL REMOVE -1", encodeIdlRemove(-1), "PNVGIDL station ID", "0..4095");
    row("Q bad address", encodeQuery("GP", "PNVG"), "Q address", "3 characters");
}

void TstNvsEncoders::outOfRangeValuesAreRefusedNamingParameterAndRange() {
    QFETCH(QString, error);
    QFETCH(int, sentences);
    QFETCH(QString, parameter);
    QFETCH(QString, range);
    QCOMPARE(sentences, 0);
    QVERIFY2(error.contains(parameter), qPrintable(error));
    QVERIFY2(error.contains(range), qPrintable(error));
}

QTEST_APPLESS_MAIN(TstNvsEncoders)
#include "tst_nvs_encoders.moc"
