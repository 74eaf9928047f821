// Section 4 input commands: every encoder byte-exact against the spec's printed checksums,
// refusals of what the receiver does not accept, the settings schema and its encoders,
// read-back from RQUERY/NQUERY, reply rules.
#include "core/settings_plan.h"
#include "decode_helper.h"
#include "examples_table.h"
#include "geostar/geostar_commands.h"
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_messages.h"
#include "geostar/geostar_schema.h"
#include "vendor_refusal_rows.h"

#include <QTest>
#include <functional>

using namespace gnss;
using namespace gnss::geostar;

namespace {

QString sent(const EncodeResult &r) {
    QStringList l;
    for (const auto &s : r.sentences) l << QString::fromStdString(s);
    return l.join('\n');
}

EncodeResult settings(std::initializer_list<KeyValue> kv) {
    std::vector<KeyValue> v(kv);
    return encodeSettings(dialect(), v);
}

EncodeResult queries(std::initializer_list<std::string> keys) {
    std::vector<std::string> v(keys);
    return encodeQueries(dialect(), v);
}

std::vector<KeyValue> extracted(const char *line) {
    return gnss::test::extractedSettings("geostar", line);
}

QString valueOf(const std::vector<KeyValue> &kv, const char *key) {
    for (const auto &p : kv)
        if (p.key == key) return QString::fromStdString(p.value);
    return "<absent>";
}

} // namespace

class TstGeostarCommands : public QObject {
    Q_OBJECT
private slots:
    void everyCommandReproducesTheSpecChecksum_data();
    void everyCommandReproducesTheSpecChecksum();
    void typedEncodersAreByteExact_data();
    void typedEncodersAreByteExact();
    void valuesTheReceiverRejectsAreRefused_data();
    void valuesTheReceiverRejectsAreRefused();
    void settingsComeWithTheirConfirmingQueryAndPortChangesLast();
    void readBackQueriesAndWriteOnlySettings();
    void rqueryAndNqueryRepliesGiveSettingValues();
    void everySchemaOptionHasItsCommand();
    void replyRulesCoverEveryCommand();
    void dialectRecord();
};

void TstGeostarCommands::everyCommandReproducesTheSpecChecksum_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    const auto examples = test::loadSpecExamples();
    for (const CommandDef &c : commands()) {
        const QString expected =
                "$GPSGG," + QString::fromUtf8(c.text.data(), int(c.text.size())) + "*" +
                QString::fromUtf8(c.specChecksum.data(), int(c.specChecksum.size()));
        if (!examples.empty()) {
            bool inSpec = false; // the spec prints this very sentence (corrected address)
            for (const auto &e : examples)
                inSpec = inSpec || (e.vendor == "geostar" &&
                                    QString::fromStdString(e.sentence()) == expected);
            QVERIFY2(inSpec, qPrintable(expected));
        }
        QTest::addRow("%s", qPrintable(expected))
                << QString::fromUtf8(c.text.data(), int(c.text.size())) << expected;
    }
    QCOMPARE(commands().size(), std::size_t(60)); // the 24 commands of section 4, every value
}

void TstGeostarCommands::everyCommandReproducesTheSpecChecksum() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const CommandDef *c = findCommand(text.toStdString());
    QVERIFY(c);
    QCOMPARE(QString::fromStdString(encodeCommand(*c)), expected);
    // And it decodes back to the same command.
    DecoderOptions o;
    o.dialect = "geostar";
    const auto d = test::decodeOne(expected, o);
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["command"].toString(), text);
}

void TstGeostarCommands::typedEncodersAreByteExact_data() {
    QTest::addColumn<std::function<EncodeResult()>>("encode");
    QTest::addColumn<QString>("expected");
    using F = std::function<EncodeResult()>;
    QTest::newRow("4.1 SWPROT") << F(encodeSwitchToBinary) << "$GPSGG,SWPROT*75";
    QTest::newRow("4.2 SAVEFL") << F(encodeSaveAlmanacs) << "$GPSGG,SAVEFL*63";
    QTest::newRow("4.3 CSTART") << F(encodeColdStart) << "$GPSGG,CSTART*6B";
    QTest::newRow("4.4 WSTART") << F(encodeWarmStart) << "$GPSGG,WSTART*7F";
    QTest::newRow("4.5 HSTART") << F(encodeHotStart) << "$GPSGG,HSTART*60";
    QTest::newRow("4.6 RQUERY") << F(encodeStatusQuery) << "$GPSGG,RQUERY*70";
    QTest::newRow("4.7 NQUERY") << F(encodeOutputQuery) << "$GPSGG,NQUERY*6C";
    const std::pair<int, const char *> bdr[] = {
            {4800, "$GPSGG,BDR004*08"},   {9600, "$GPSGG,BDR009*05"},
            {19200, "$GPSGG,BDR019*04"},  {38400, "$GPSGG,BDR038*07"},
            {57600, "$GPSGG,BDR057*0E"},  {115200, "$GPSGG,BDR115*09"},
            {230400, "$GPSGG,BDR230*0D"}, {460800, "$GPSGG,BDR460*0E"},
            {921600, "$GPSGG,BDR921*06"}};
    for (auto [baud, s] : bdr)
        QTest::addRow("4.8 BDR %d", baud) << F([b = baud] { return encodeBaudRate(b); }) << s;
    QTest::newRow("4.9 STOP01") << F([] { return encodeStopBits(1); }) << "$GPSGG,STOP01*71";
    QTest::newRow("4.9 STOP02") << F([] { return encodeStopBits(2); }) << "$GPSGG,STOP02*72";
    const char *on[] = {"$GPSGG,GGA ON*08", "$GPSGG,GLL ON*0E", "$GPSGG,GSA ON*1C",
                        "$GPSGG,GSV ON*0B", "$GPSGG,RMC ON*15", "$GPSGG,VTG ON*0C",
                        "$GPSGG,ZDA ON*16", "$GPSGG,DTM ON*14", "$GPSGG,RLM ON*1A"};
    const char *off[] = {"$GPSGG,GGAOFF*66", "$GPSGG,GLLOFF*60", "$GPSGG,GSAOFF*72",
                         "$GPSGG,GSVOFF*65", "$GPSGG,RMCOFF*7B", "$GPSGG,VTGOFF*62",
                         "$GPSGG,ZDAOFF*78", "$GPSGG,DTMOFF*7A", "$GPSGG,RLMOFF*74"};
    const char *msg[] = {"GGA", "GLL", "GSA", "GSV", "RMC", "VTG", "ZDA", "DTM", "RLM"};
    for (int i = 0; i < 9; ++i) {
        const std::string m = msg[i];
        QTest::addRow("4.%d %s ON", 10 + i, msg[i])
                << F([m] { return encodeOutput(m, true); }) << on[i];
        QTest::addRow("4.%d %sOFF", 10 + i, msg[i])
                << F([m] { return encodeOutput(m, false); }) << off[i];
    }
    QTest::newRow("4.19 NMEAV2") << F([] { return encodeNmeaVersion(2); }) << "$GPSGG,NMEAV2*0B";
    QTest::newRow("4.19 NMEAV4") << F([] { return encodeNmeaVersion(4); }) << "$GPSGG,NMEAV4*0D";
    QTest::newRow("4.20 RATE01") << F([] { return encodeRate(1); }) << "$GPSGG,RATE01*6B";
    QTest::newRow("4.20 RATE02") << F([] { return encodeRate(2); }) << "$GPSGG,RATE02*68";
    QTest::newRow("4.20 RATE05") << F([] { return encodeRate(5); }) << "$GPSGG,RATE05*6F";
    QTest::newRow("4.20 RATE10") << F([] { return encodeRate(10); }) << "$GPSGG,RATE10*6B";
    QTest::newRow("4.21 PSM ON") << F([] { return encodePowerSaving(true); }) << "$GPSGG,PSM ON*07";
    QTest::newRow("4.21 PSMOFF") << F([] { return encodePowerSaving(false); })
                                 << "$GPSGG,PSMOFF*69";
    const char *elev[] = {"77", "74", "75", "7A", "7B", "73", "72", "71", "70", "77", "76"};
    for (int deg = 5; deg <= 15; ++deg)
        QTest::addRow("4.22 ELEV%02d", deg)
                << F([deg] { return encodeElevationMask(deg); })
                << QString("$GPSGG,ELEV%1*%2").arg(deg, 2, 10, QChar('0')).arg(elev[deg - 5]);
    QTest::newRow("4.23 DATP90") << F([] { return encodeDatum("P90"); }) << "$GPSGG,DATP90*60";
    QTest::newRow("4.23 DATW84") << F([] { return encodeDatum("W84"); }) << "$GPSGG,DATW84*62";
    QTest::newRow("4.24 NVSGPS") << F([] { return encodeConstellations("GPS"); })
                                 << "$GPSGG,NVSGPS*67";
    QTest::newRow("4.24 NVSGLN") << F([] { return encodeConstellations("GLN"); })
                                 << "$GPSGG,NVSGLN*66";
    QTest::newRow("4.24 NVSMIX") << F([] { return encodeConstellations("MIX"); })
                                 << "$GPSGG,NVSMIX*7F";
}

void TstGeostarCommands::typedEncodersAreByteExact() {
    QFETCH(std::function<EncodeResult()>, encode);
    QFETCH(QString, expected);
    const EncodeResult r = encode();
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(sent(r), expected);
}

void TstGeostarCommands::valuesTheReceiverRejectsAreRefused_data() {
    test::addRefusedSettingColumns();
    QTest::newRow("ELEV04") << "nav.ELEV"
                            << "4"
                            << "nav.ELEV: 4 is out of range; accepted: 5..15 deg";
    QTest::newRow("ELEV16") << "ELEV"
                            << "16"
                            << "nav.ELEV: 16 is out of range; accepted: 5..15 deg";
    QTest::newRow("RATE03") << "RATE"
                            << "3"
                            << "output.RATE: '3' is not one of: 1, 2, 5, 10";
    QTest::newRow("BDR 1200") << "BDR"
                              << "1200"
                              << "port.BDR: '1200' is not one of: 4800";
    QTest::newRow("STOP03") << "STOP"
                            << "3"
                            << "port.STOP: '3' is not one of: 1, 2";
    QTest::newRow("NMEA v3") << "NMEAV"
                             << "3"
                             << "output.NMEAV: '3' is not one of: 2, 4";
    QTest::newRow("GGA maybe") << "GGA"
                               << "maybe"
                               << "output.GGA: expected 0 or 1";
    QTest::newRow("user datum") << "DAT"
                                << "999"
                                << "cannot be set with an NMEA command";
    QTest::newRow("BeiDou") << "NVS"
                            << "BDS"
                            << "nav.NVS: 'BDS' is not one of: GPS, GLN, MIX";
    QTest::newRow("unknown") << "output.GST"
                             << "1"
                             << "unknown setting 'output.GST'";
}

void TstGeostarCommands::valuesTheReceiverRejectsAreRefused() {
    // Together with a valid setting: nothing at all is built.
    test::checkRefusedSetting([](const KeyValue &kv) { return settings({{"GGA", "1"}, kv}); });
}

void TstGeostarCommands::settingsComeWithTheirConfirmingQueryAndPortChangesLast() {
    const EncodeResult r = settings({{"BDR", "115200"},
                                     {"GGA", "on"},
                                     {"ELEV", "05"},
                                     {"RATE", "5"},
                                     {"DAT", "P90"},
                                     {"START", "hot"}});
    QVERIFY2(r.ok(), r.error.c_str());
    // The set commands grouped by the query that reports them (schema rows), in the order given;
    // then the confirming queries; then the restart and the port's speed.
    QCOMPARE(sent(r), QString("$GPSGG,GGA ON*08\n$GPSGG,RATE05*6F\n$GPSGG,ELEV05*77\n"
                              "$GPSGG,DATP90*60\n$GPSGG,NQUERY*6C\n$GPSGG,RQUERY*70\n"
                              "$GPSGG,HSTART*60\n$GPSGG,BDR115*09"));
    // Write-only alone: no query to confirm it.
    QCOMPARE(sent(settings({{"ELEV", "10"}})), QString("$GPSGG,ELEV10*73"));
    QCOMPARE(sent(settings({{"SWPROT", "binary"}, {"RLM", "0"}})),
             QString("$GPSGG,RLMOFF*74\n$GPSGG,NQUERY*6C\n$GPSGG,SWPROT*75"));
}

void TstGeostarCommands::readBackQueriesAndWriteOnlySettings() {
    QCOMPARE(sent(queries({"GGA", "RATE", "NMEAV"})), QString("$GPSGG,NQUERY*6C"));
    QCOMPARE(sent(queries({"DAT", "NVS", "PSM", "GSV"})),
             QString("$GPSGG,RQUERY*70\n$GPSGG,NQUERY*6C"));
    QCOMPARE(sent(queries({"all"})), QString("$GPSGG,NQUERY*6C\n$GPSGG,RQUERY*70"));
    for (const char *wo : {"ELEV", "BDR", "STOP", "START"}) {
        const EncodeResult r = queries({wo});
        QVERIFY2(!r.ok() && r.error.find("write-only") != std::string::npos, wo);
        const SettingDef *d = findSetting(dialect().settings, wo);
        QVERIFY(d);
        QVERIFY(d->access == SettingAccess::WriteOnly);
    }
}

void TstGeostarCommands::rqueryAndNqueryRepliesGiveSettingValues() {
    const auto n = extracted("$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71");
    QCOMPARE(valueOf(n, "output.RATE"), QString("1"));
    QCOMPARE(valueOf(n, "output.NMEAV"), QString("2"));
    QCOMPARE(valueOf(n, "output.GGA"), QString("1"));
    QCOMPARE(valueOf(n, "output.GLL"), QString("0"));
    QCOMPARE(valueOf(n, "output.GSA"), QString("1"));
    QCOMPARE(valueOf(n, "output.GSV"), QString("1"));
    QCOMPARE(valueOf(n, "output.RMC"), QString("0"));
    QCOMPARE(valueOf(n, "output.VTG"), QString("0"));
    QCOMPARE(valueOf(n, "output.ZDA"), QString("1"));
    QCOMPARE(valueOf(n, "output.DTM"), QString("1"));
    QCOMPARE(valueOf(n, "output.RLM"), QString("0"));
    QCOMPARE(n.size(), std::size_t(11)); // the unknown 7th position names no setting
    const auto q = extracted("$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C");
    QCOMPARE(valueOf(q, "output.RATE"), QString("1"));
    QCOMPARE(valueOf(q, "power.PSM"), QString("0"));
    QCOMPARE(valueOf(q, "nav.DAT"), QString("999")); // bits 15:14 = 2: user-defined
    QCOMPARE(valueOf(q, "nav.NVS"), QString("MIX")); // GLONASS, GPS and Galileo in use
    // Every extracted value is valid for its setting.
    for (const auto &kv : n)
        QVERIFY(validateSetting(*findSetting(dialect().settings, kv.key), kv.value).empty());
    for (const auto &kv : q)
        QVERIFY(validateSetting(*findSetting(dialect().settings, kv.key), kv.value).empty());
    QVERIFY(extracted("$GPSGG,CSTART*6B").empty());
}

void TstGeostarCommands::everySchemaOptionHasItsCommand() {
    for (const SettingDef &d : dialect().settings) {
        QVERIFY2(!d.readBack.empty() && !d.write.empty() && !d.help.empty(), d.key.data());
        if (d.type == SettingType::Bool) {
            QVERIFY(findCommandFor(d.key, "0") && findCommandFor(d.key, "1"));
        } else if (d.type == SettingType::Integer) {
            for (int v = int(*d.min); v <= int(*d.max); ++v)
                QVERIFY(findCommandFor(d.key, std::to_string(v)));
        } else {
            for (const auto &o : d.options)
                QVERIFY2(findCommandFor(d.key, o.value) || o.value == "999", o.value.data());
        }
    }
    // And every command that sets something names a setting of the schema.
    for (const CommandDef &c : commands())
        QVERIFY2(c.settingKey.empty() || findSetting(dialect().settings, c.settingKey),
                 c.text.data());
}

void TstGeostarCommands::replyRulesCoverEveryCommand() {
    const auto rules = dialect().replyRules;
    QCOMPARE(rules.size(), commands().size());
    Sentence cmd, reply, other;
    QVERIFY(cmd.parse("$GPSGG,RQUERY*70"));
    QVERIFY(reply.parse("$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C"));
    QVERIFY(other.parse("$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71"));
    for (const ReplyRule &r : rules) {
        QCOMPARE(r.commandAddress, std::string_view("GPSGG"));
        const CommandDef *c = findCommand(r.firstField);
        QVERIFY(c);
        QVERIFY(r.effect == c->effect);
        QVERIFY(!r.description.empty());
        ReplyProgress p;
        if (r.firstField == "RQUERY") {
            QVERIFY(r.classify(cmd, reply, p) == ReplyVerdict::Accepted);
            QVERIFY(r.classify(cmd, other, p) == ReplyVerdict::NotMine);
            QVERIFY(r.classify(cmd, cmd, p) == ReplyVerdict::NotMine); // our own echo
        } else if (r.firstField == "NQUERY") {
            QVERIFY(r.classify(cmd, other, p) == ReplyVerdict::Accepted);
            QVERIFY(r.classify(cmd, reply, p) == ReplyVerdict::NotMine);
        } else {
            QVERIFY2(r.classify == nullptr, r.firstField.data()); // not acknowledged
        }
    }
    auto effectOf = [&](std::string_view t) { return findCommand(t)->effect; };
    QVERIFY(effectOf("CSTART") == CommandEffect::ResetsReceiver);
    QVERIFY(effectOf("WSTART") == CommandEffect::ResetsReceiver);
    QVERIFY(effectOf("HSTART") == CommandEffect::ResetsReceiver);
    QVERIFY(effectOf("BDR921") == CommandEffect::ChangesBaud);
    QVERIFY(effectOf("STOP02") == CommandEffect::ChangesBaud);
    QVERIFY(effectOf("SWPROT") == CommandEffect::ChangesProtocol);
    QVERIFY(effectOf("RATE10") == CommandEffect::ChangesOutput);
}

void TstGeostarCommands::dialectRecord() {
    const Dialect &d = dialect();
    QCOMPARE(d.id, std::string_view("geostar"));
    QCOMPARE(d.displayName, std::string_view("GeoStar GeoS-5"));
    QCOMPARE(d.probeCommand, std::string_view("$GPSGG,RQUERY*70"));
    QCOMPARE(d.defaultBaud, 115200);
    QCOMPARE(d.commandNames.size(), commands().size());
    for (const CommandDef &c : commands()) {
        bool named = false;
        for (auto n : d.commandNames) named = named || n == "GPSGG," + std::string(c.text);
        QVERIFY2(named, c.text.data());
    }
    QVERIFY(makeBuiltinRegistry().find("geostar") == &d);
}

QTEST_APPLESS_MAIN(TstGeostarCommands)
#include "tst_geostar_commands.moc"
