// The Nemerix dialect record, its settings schema as data, settings → commands
// (encodeSettings / encodeQueries), PNMRX603 reports → settings (extractSettings), and the
// reply rules the command queue uses.
#include "core/settings_plan.h"
#include "decode_helper.h"
#include "nemerix/nemerix_dialect.h"
#include "vendor_refusal_rows.h"
#include "vendor_test_rows.h"

#include <QJsonArray>
#include <QTest>

#include <set>

using gnss::test::textRow;

namespace {

const gnss::Dialect &D() {
    return gnss::nemerix::dialect();
}

// Decodes a line and collects what extractSettings reads from it.
std::vector<gnss::KeyValue> extract(const std::string &line) {
    return gnss::test::extractedSettings("nemerix", line);
}

QString joined(const std::vector<std::string> &v) {
    QStringList l;
    for (const auto &s : v) l << QString::fromStdString(s);
    return l.join(" ");
}

QString joined(const std::vector<gnss::KeyValue> &v) {
    QStringList l;
    for (const auto &kv : v) l << QString::fromStdString(kv.key + "=" + kv.value);
    return l.join(" ");
}

gnss::ReplyVerdict classify(const char *command, const char *reply, gnss::ReplyProgress &p) {
    const gnss::ReplyRule *rule = nullptr;
    gnss::Sentence c, r;
    c.parse(command);
    r.parse(reply);
    for (const auto &rr : D().replyRules)
        if (rr.commandAddress == c.address()) rule = &rr;
    if (!rule || !rule->classify) return gnss::ReplyVerdict::NotMine;
    return rule->classify(c, r, p);
}

} // namespace

class TstNemerixSettings : public QObject {
    Q_OBJECT
private slots:
    void dialectRecordIsComplete();
    void probeIsTheVersionRequestWithItsRealChecksum();
    void everyCommandNameHasARuleAndAnEncoder();
    void schemaRowsAreConsistent();
    void settingsEncodeToCommands_data();
    void settingsEncodeToCommands();
    void refusedSettingsBuildNothing_data();
    void refusedSettingsBuildNothing();
    void readableSettingsAreQueriedWithOneSettingsRequest();
    void writeOnlySettingsCannotBeQueried();
    void settingsReportMessagesGiveSettingsBack_data();
    void settingsReportMessagesGiveSettingsBack();
    void readBackValuesEncodeAgain();
    void commandsCarryTheSettingsTheyWrite_data();
    void commandsCarryTheSettingsTheyWrite();
    void everyEncodedSettingComesBackFromItsCommand();
    void versionRequestIsAnsweredByVersionReport();
    void settingsRequestIsAnsweredByFiveMessages();
    void silentCommandsDeclareTheirEffect();
};

void TstNemerixSettings::dialectRecordIsComplete() {
    QCOMPARE(QString::fromUtf8(D().id.data(), D().id.size()), QString("nemerix"));
    QCOMPARE(QString::fromUtf8(D().displayName.data(), D().displayName.size()),
             QString("Nemerix VT002"));
    QVERIFY(D().checksumOptional);
    QCOMPARE(D().defaultBaud, 9600);
    QCOMPARE(D().rules.size(), std::size_t(20));
    QVERIFY(D().extractSettings);
    QVERIFY(!D().settings.empty());
    QVERIFY(!D().replyRules.empty());
    const auto registry = gnss::makeBuiltinRegistry();
    QCOMPARE(registry.find("nemerix"), &D());
    for (const auto &r : D().rules) QVERIFY(r.match == gnss::AddressMatch::Whole);
}

void TstNemerixSettings::probeIsTheVersionRequestWithItsRealChecksum() {
    QCOMPARE(QString::fromUtf8(D().probeCommand.data(), D().probeCommand.size()),
             QString("$PNMRX600*6F"));
    gnss::Sentence s;
    QVERIFY(s.parse(D().probeCommand));
    QVERIFY(s.checksum() == gnss::ChecksumStatus::Ok);
    // The answer to the probe is recognised by the reply rule.
    gnss::ReplyProgress p;
    QVERIFY(classify("$PNMRX600*6F", "$PNMRX600,VT002,1.05", p) == gnss::ReplyVerdict::Accepted);
}

void TstNemerixSettings::everyCommandNameHasARuleAndAnEncoder() {
    std::set<std::string_view> rules;
    for (const auto &r : D().rules) rules.insert(r.address);
    std::set<std::string_view> replies;
    for (const auto &r : D().replyRules) replies.insert(r.commandAddress);
    for (auto name : D().commandNames) {
        QVERIFY2(rules.count(name), std::string(name).c_str());
        QVERIFY2(replies.count(name), std::string(name).c_str());
    }
    QCOMPARE(D().commandNames.size(), std::size_t(15));
}

void TstNemerixSettings::schemaRowsAreConsistent() {
    std::set<std::string_view> keys;
    QStringList groups;
    for (const auto &d : D().settings) {
        QVERIFY2(keys.insert(d.key).second, "duplicate key");
        QVERIFY(!d.label.empty() && !d.group.empty() && !d.help.empty());
        QVERIFY2(d.write.substr(0, 6) == "$PNMRX", std::string(d.key).c_str());
        const bool readable = d.access != gnss::SettingAccess::WriteOnly;
        QVERIFY2(readable == !d.readBack.empty(), std::string(d.key).c_str());
        if (d.type == gnss::SettingType::Enum) QVERIFY(!d.options.empty());
        if (!d.defaultValue.empty() && d.type != gnss::SettingType::List)
            QVERIFY2(gnss::validateSetting(d, d.defaultValue).empty(), std::string(d.key).c_str());
        const QString g = QString::fromUtf8(d.group.data(), d.group.size());
        if (!groups.contains(g)) groups << g;
    }
    // The groups the issue asks for.
    for (const char *g :
         {"Serial port", "NMEA output", "Datum", "Fix masks", "Navigation mode", "Power mode"})
        QVERIFY2(groups.contains(g), g);
}

void TstNemerixSettings::settingsEncodeToCommands_data() {
    QTest::addColumn<QStringList>("values");
    QTest::addColumn<QString>("sentences");
    QTest::newRow("baud alone") << QStringList{"serial.baud=4800"} << "$PNMRX100,0,4800,0*48";
    QTest::newRow("serial all") << QStringList{"serial.parity=2", "serial.baud=57600",
                                               "serial.protocol=0"}
                                << "$PNMRX100,0,57600,2*72";
    QTest::newRow("rates in one sentence")
            << QStringList{"rate.ZDA=0", "rate.GSV=2", "GGA=1"} << "$PNMRX103,GGA,1,GSV,2,ZDA,0*04";
    QTest::newRow("sequence then rates") << QStringList{"rate.GSA=3", "output.sequence=GGA;GLL;GSA"}
                                         << "$PNMRX108,GGA,GLL,GSA*1F $PNMRX103,GSA,3*0D";
    QTest::newRow("sequence typed with spaces")
            << QStringList{"output.sequence= GGA; GLL ,GSA "} << "$PNMRX108,GGA,GLL,GSA*1F";
    QTest::newRow("nemerix messages")
            << QStringList{"nmrx.301=2", "nmrx.300=1"} << "$PNMRX107,300,1,301,2*6D";
    QTest::newRow("internal datum")
            << QStringList{"datum.mapDatum=216", "datum.correction=1"} << "$PNMRX106,1,216,*46";
    QTest::newRow("user datum") << QStringList{"datum.mapDatum=500",
                                               "datum.dx=-2000",
                                               "datum.dy=-2000",
                                               "datum.dz=-2000",
                                               "datum.inverseFlattening=298.257224",
                                               "datum.semiMajorAxis=6378137"}
                                << "$PNMRX106,0,500,-2000,-2000,-2000,8257224,8137000*69";
    QTest::newRow("fix masks in one sentence")
            << QStringList{"fix.minSnr=35", "fix.timeZone=-2:0", "fix.maxPdop=6",
                           "nav.mode=4",    "nav.dynamics=1",    "fix.maxAltitude=18000"}
            << "$PNMRX110,0,-2:0,1,60,4,35,7,4,9,1,10,18000*7A";
    QTest::newRow("channels") << QStringList{"nav.channels=16"} << "$PNMRX101,,,,,,,16,*6E";
    QTest::newRow("power low") << QStringList{"power.mode=1", "power.offPeriod=5"}
                               << "$PNMRX112,1,5*6F";
    QTest::newRow("power off period implies LDCM1")
            << QStringList{"power.offPeriod=10"} << "$PNMRX112,1,10*5B";
    QTest::newRow("power full") << QStringList{"power.mode=0"} << "$PNMRX112,0*77";
    QTest::newRow("baud goes last") << QStringList{"serial.baud=19200", "fix.minElevation=10"}
                                    << "$PNMRX110,5,10*5D $PNMRX100,0,19200,0*7E";
}

void TstNemerixSettings::settingsEncodeToCommands() {
    QFETCH(QStringList, values);
    QFETCH(QString, sentences);
    std::vector<gnss::KeyValue> kv;
    for (const auto &v : values) {
        const auto eq = v.indexOf('=');
        kv.push_back({v.left(eq).toStdString(), v.mid(eq + 1).toStdString()});
    }
    const auto r = encodeSettings(D(), kv);
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(joined(r.sentences), sentences);
}

void TstNemerixSettings::refusedSettingsBuildNothing_data() {
    gnss::test::addRefusedSettingColumns();
    textRow("unknown key", {"fix.nothing", "1", "unknown setting"});
    textRow("baud", {"serial.baud", "115200", "serial.baud"});
    textRow("snr", {"fix.minSnr", "46", "fix.minSnr: 46 is out of range; accepted: 20..45 dB-Hz"});
    textRow("rate", {"rate.GGA", "10", "rate.GGA: 10 is out of range; accepted: 0..9 s"});
    textRow("time zone", {"fix.timeZone", "-14:0", "fix.timeZone"});
    textRow("datum hole", {"datum.mapDatum", "300", "0..218"});
    textRow("user datum incomplete", {"datum.mapDatum", "500", "needs"});
    textRow("offset without datum", {"datum.dx", "5", "datum.mapDatum: required"});
    textRow("parity without baud", {"serial.parity", "1", "serial.baud: required"});
    textRow("sequence unknown", {"output.sequence", "GGA;GNS", "'GNS'"});
    // Found by fuzz_settings_roundtrip: the space was dropped and GSV sent.
    textRow("sequence id with a space", {"output.sequence", "ZDA;G SV;RMC", "'G SV'"});
    textRow("channels", {"nav.channels", "8", "nav.channels: 8 is out of range"});
    textRow("nav mode", {"nav.mode", "3", "nav.mode"});
    textRow("off period", {"power.offPeriod", "4", "5..10"});
    textRow("injection", {"fix.timeZone", "1:0*00", "not allowed"});
}

void TstNemerixSettings::refusedSettingsBuildNothing() {
    // A valid value next to the refused one: still nothing is built.
    gnss::test::checkRefusedSetting([](const gnss::KeyValue &refused) {
        std::vector<gnss::KeyValue> kv = {{"fix.minSnr", "30"}, refused};
        if (refused.key == "fix.minSnr") kv.erase(kv.begin());
        return encodeSettings(D(), kv);
    });
}

void TstNemerixSettings::readableSettingsAreQueriedWithOneSettingsRequest() {
    const std::vector<std::string> keys = {"fix.minSnr", "datum.mapDatum", "rate.GSV",
                                           "fix.timeZone", "nav.channels"};
    const auto r = encodeQueries(D(), keys);
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(joined(r.sentences), QString("$PNMRX603*6C"));
}

void TstNemerixSettings::writeOnlySettingsCannotBeQueried() {
    for (const char *k : {"serial.baud", "power.mode", "output.sequence", "fix.maxVdop"}) {
        const std::vector<std::string> keys = {k};
        const auto r = encodeQueries(D(), keys);
        QVERIFY(!r.ok());
        QVERIFY(r.sentences.empty());
        QVERIFY2(r.error.find("write-only") != std::string::npos, r.error.c_str());
    }
    const std::vector<std::string> unknown = {"nope"};
    QVERIFY(!encodeQueries(D(), unknown).ok());
}

void TstNemerixSettings::settingsReportMessagesGiveSettingsBack_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("settings");
    QTest::addColumn<QString>("json");
    QTest::newRow("message 0") << "$PNMRX603,0,1,2,3,4,5,6,7,1,0,3,3,1,1,0,0000001F,00002580"
                               << "rate.GGA=1 rate.GLL=0 rate.GSA=3 rate.GSV=3 rate.RMC=1 "
                                  "rate.VTG=1 rate.ZDA=0"
                               << R"("uart_settings":"00002580")";
    QTest::newRow("message 1") << "$PNMRX603,1,0C,FF,FE,01,7F,80,FF,00,1,0,-2,30"
                               << "fix.timeZone=-2:30"
                               << R"("alpha1_raw":"FF")";
    QTest::newRow("message 2") << "$PNMRX603,2,10.0,8.5,00000005,30.0,5.0,16,12"
                               << "fix.maxPdop=10 fix.maxHdop=8.5 fix.minSnr=30 "
                                  "fix.minElevation=5 nav.channels=16"
                               << R"("excluded_svs":[1,3])";
    QTest::newRow("message 3") << "$PNMRX603,3,1200,1400,600,2,250"
                               << "fix.noiseFloor=600 fix.altitude2d=250"
                               << R"("kalman_mode":2)";
    QTest::newRow("message 4") << "$PNMRX603,4,0,500,-2000,-2000,-2000,8257224,8137000"
                               << "datum.correction=0 datum.mapDatum=500 datum.dx=-2000 "
                                  "datum.dy=-2000 datum.dz=-2000 "
                                  "datum.inverseFlattening=298.257 "
                                  "datum.semiMajorAxis=6378137.000"
                               << R"("semi_major_axis_m":6378137)";
}

void TstNemerixSettings::settingsReportMessagesGiveSettingsBack() {
    QFETCH(QString, line);
    QFETCH(QString, settings);
    QFETCH(QString, json);
    QCOMPARE(joined(extract(line.toStdString())), settings);
    gnss::DecoderOptions o;
    o.dialect = "nemerix";
    const auto d = gnss::test::decodeOne(line, o);
    QVERIFY2(d.ok, qPrintable(d.error));
    const QString text = QString::fromUtf8(QJsonDocument(d.data).toJson(QJsonDocument::Compact));
    QVERIFY2(text.contains(json), qPrintable(text));
}

void TstNemerixSettings::readBackValuesEncodeAgain() {
    // Everything read back is a valid value for the same key: a profile saved from a receiver
    // can be written to another.
    for (const char *line :
         {"$PNMRX603,0,1,2,3,4,5,6,7,1,0,3,3,1,1,0,0000001F,00002580",
          "$PNMRX603,1,0C,FF,FE,01,7F,80,FF,00,1,0,-2,30",
          "$PNMRX603,2,10.0,8.5,00000005,30.0,5.0,16,12", "$PNMRX603,3,1200,1400,600,2,250",
          "$PNMRX603,4,0,500,-2000,-2000,-2000,8257224,8137000"}) {
        const auto kv = extract(line);
        QVERIFY(!kv.empty());
        const auto r = encodeSettings(D(), kv);
        QVERIFY2(r.ok(), (std::string(line) + ": " + r.error).c_str());
    }
}

void TstNemerixSettings::commandsCarryTheSettingsTheyWrite_data() {
    // What a receiver applying the command holds afterwards (a simulated VT002 applies commands
    // through extractSettings).
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("settings");
    textRow("100 port",
            {"$PNMRX100,0,4800,0*48", "serial.protocol=0 serial.baud=4800 serial.parity=0"});
    textRow("100 without baud", {"$PNMRX100,1,,2", ""});
    textRow("101 channels", {"$PNMRX101,,,,,,,14,", "nav.channels=14"});
    textRow("101 position", {"$PNMRX101,-742507,-5462738, 3196706,*4F", ""});
    textRow("104 channels", {"$PNMRX104,,,,,,,,,16", "nav.channels=16"});
    textRow("103 rates",
            {"$PNMRX103, GSV, 2,GGA, 1,ZDA, 0*04", "rate.GSV=2 rate.GGA=1 rate.ZDA=0"});
    textRow("103 ALL",
            {"$PNMRX103, ALL, 2*18", "rate.GGA=2 rate.GLL=2 rate.GSA=2 rate.GSV=2 rate.RMC=2 "
                                     "rate.VTG=2 rate.ZDA=2"});
    textRow("107 one", {"$PNMRX107, 301, 2*6F", "nmrx.301=2"});
    textRow("107 ALL",
            {"$PNMRX107, ALL, 2*1C", "nmrx.300=2 nmrx.301=2 nmrx.302=2 nmrx.303=2 nmrx.304=2"});
    textRow("108 sequence",
            {"$PNMRX108,RMC,GGA,RMC", "output.sequence=RMC;GGA rate.GGA=1 rate.GLL=0 rate.GSA=0 "
                                      "rate.GSV=0 rate.RMC=1 rate.VTG=0 rate.ZDA=0"});
    textRow("106 user datum",
            {"$PNMRX106, 0,500, -2000,-2000,-2000, 8257224, 8137000*69",
             "datum.correction=0 datum.mapDatum=500 datum.dx=-2000 datum.dy=-2000 "
             "datum.dz=-2000 datum.inverseFlattening=298.257224 "
             "datum.semiMajorAxis=6378137.000"});
    textRow("106 WGS 84", {"$PNMRX106, 1, 216,*46", "datum.correction=1 datum.mapDatum=216"});
    textRow("110 time zone", {"$PNMRX110, 0,-2:0*6C", "fix.timeZone=-2:0"});
    textRow("110 masks", {"$PNMRX110,0,-0:30,1,65,3,100,4,35,5,10,6,700,7,4,8,250,9,1,10,"
                          "20000",
                          "fix.timeZone=-0:30 fix.maxPdop=6.5 fix.maxVdop=10 "
                          "fix.minSnr=35 fix.minElevation=10 fix.noiseFloor=700 "
                          "nav.mode=4 fix.altitude2d=250 nav.dynamics=1 "
                          "fix.maxAltitude=20000"});
    textRow("112 low power", {"$PNMRX112, 1, 5*6F", "power.mode=1 power.offPeriod=5"});
    textRow("111 reset", {"$PNMRX111,COLD", ""});
    textRow("603 request", {"$PNMRX603*6C", ""});
}

void TstNemerixSettings::commandsCarryTheSettingsTheyWrite() {
    QFETCH(QString, line);
    QFETCH(QString, settings);
    QCOMPARE(joined(extract(line.toStdString())), settings);
}

void TstNemerixSettings::everyEncodedSettingComesBackFromItsCommand() {
    // encodeSettings → the receiver's decoders → extractSettings gives each value back (a user
    // datum's fields with datum 500 only: PNMRX106 carries them for it alone).
    const std::vector<gnss::KeyValue> values = {
            {"serial.protocol", "0"},
            {"serial.baud", "19200"},
            {"serial.parity", "1"},
            {"rate.GGA", "2"},
            {"rate.GSV", "5"},
            {"rate.ZDA", "0"},
            {"output.sequence", "RMC;GGA;GSV"},
            {"nmrx.303", "2"},
            {"datum.correction", "0"},
            {"datum.mapDatum", "500"},
            {"datum.dx", "10"},
            {"datum.dy", "-20"},
            {"datum.dz", "30"},
            {"datum.inverseFlattening", "298.257223"},
            {"datum.semiMajorAxis", "6378137"},
            {"fix.timeZone", "5:30"},
            {"fix.maxPdop", "8.5"},
            {"fix.maxHdop", "4.5"},
            {"fix.maxVdop", "6.5"},
            {"fix.minSnr", "30"},
            {"fix.minElevation", "10"},
            {"fix.noiseFloor", "700"},
            {"fix.altitude2d", "120"},
            {"fix.maxAltitude", "20000"},
            {"nav.mode", "4"},
            {"nav.dynamics", "1"},
            {"nav.channels", "14"},
            {"power.mode", "1"},
            {"power.offPeriod", "7"},
    };
    const auto r = encodeSettings(D(), values);
    QVERIFY2(r.ok(), r.error.c_str());
    std::vector<gnss::KeyValue> back;
    for (const std::string &s : r.sentences) {
        const auto one = extract(s);
        back.insert(back.end(), one.begin(), one.end());
    }
    for (const auto &kv : values) {
        std::optional<std::string> got; // the last value carried back wins
        for (const auto &b : back)
            if (b.key == kv.key) got = b.value;
        QVERIFY2(got, kv.key.c_str());
        const gnss::SettingDef *def = gnss::findSetting(D().settings, kv.key);
        if (def->type == gnss::SettingType::Real || def->type == gnss::SettingType::Integer)
            QVERIFY2(std::stod(*got) == std::stod(kv.value), (kv.key + " = " + *got).c_str());
        else
            QCOMPARE(*got, kv.value);
    }
}

void TstNemerixSettings::versionRequestIsAnsweredByVersionReport() {
    gnss::ReplyProgress p;
    QVERIFY(classify("$PNMRX600*6F", "$GPGGA,1,2,3", p) == gnss::ReplyVerdict::NotMine);
    QVERIFY(classify("$PNMRX600*6F", "$PNMRX600", p) == gnss::ReplyVerdict::NotMine); // echo
    QVERIFY(classify("$PNMRX600*6F", "$PNMRX603,0,1", p) == gnss::ReplyVerdict::NotMine);
    QVERIFY(classify("$PNMRX600*6F", "$PXYZW600,VT002 2.1", p) == gnss::ReplyVerdict::Accepted);
    // The report decodes, fields kept as sent.
    gnss::DecoderOptions o;
    o.dialect = "nemerix";
    const auto d = gnss::test::decodeOne("$PNMRX600,NMRX-VT002,2.10,Jan 12 2006", o);
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["version"].toString(), QString("NMRX-VT002,2.10,Jan 12 2006"));
    const auto flash = gnss::test::decodeOne("$PNMRX602,FC-1.3", o);
    QCOMPARE(flash.data["fields"].toArray()[0].toString(), QString("FC-1.3"));
}

void TstNemerixSettings::settingsRequestIsAnsweredByFiveMessages() {
    gnss::ReplyProgress p;
    for (int n = 0; n < 4; ++n) {
        const std::string line = "$PNMRX603," + std::to_string(n) + ",1";
        QCOMPARE(classify("$PNMRX603*6C", line.c_str(), p), gnss::ReplyVerdict::Partial);
    }
    QVERIFY(classify("$PNMRX603*6C", "$GPRMC,1", p) == gnss::ReplyVerdict::NotMine);
    QCOMPARE(classify("$PNMRX603*6C", "$PNMRX603,4,0,216,0,0,0,0,0", p),
             gnss::ReplyVerdict::Accepted);
    QCOMPARE(p.received, 5);
    QCOMPARE(p.expected, 5);
}

void TstNemerixSettings::silentCommandsDeclareTheirEffect() {
    auto effectOf = [](std::string_view address) {
        for (const auto &r : D().replyRules)
            if (r.commandAddress == address) return r.effect;
        return gnss::CommandEffect::None;
    };
    QVERIFY(effectOf("PNMRX100") == gnss::CommandEffect::ChangesBaud);
    QVERIFY(effectOf("PNMRX111") == gnss::CommandEffect::ResetsReceiver);
    QVERIFY(effectOf("PNMRX601") == gnss::CommandEffect::ChangesProtocol);
    QVERIFY(effectOf("PNMRX103") == gnss::CommandEffect::ChangesOutput);
    for (const auto &r : D().replyRules)
        if (r.commandAddress != "PNMRX600" && r.commandAddress != "PNMRX603")
            QVERIFY(r.classify == nullptr);
}

QTEST_APPLESS_MAIN(TstNemerixSettings)
#include "tst_nemerix_settings.moc"
