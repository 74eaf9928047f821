// The NVS settings schema and dialect record: every Table 4 parameter with its default, every
// group of the issue, generic encodeSettings / encodeQueries / extractSettings, and
// `gnss-cli schema nvs` / `gnss-cli encode nvs` end to end.
#include "builtin/dialects.h"
#include "core/settings_plan.h"
#include "core/stream_decoder.h"
#include "decode_helper.h"
#include "nvs/nvs_dialect.h"
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_schema.h"
#include "vendor_refusal_rows.h"
#include "vendor_test_rows.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTest>

using namespace gnss;
using gnss::test::textRow;

namespace {

// Decodes `line` with the nvs dialect and collects what extractSettings reads from it.
std::vector<KeyValue> extract(const std::string &line) {
    return gnss::test::extractedSettings("nvs", line);
}

QStringList lines(const EncodeResult &r) {
    QStringList l;
    for (const auto &s : r.sentences) l << QString::fromStdString(s).section('*', 0, 0);
    return l;
}

QString cliPath() {
    return QStringLiteral(GNSS_CLI_PATH);
}

} // namespace

class TstNvsSchema : public QObject {
    Q_OBJECT
private slots:
    void dialectRecordIsComplete();
    void everyProprietaryAddressHasAWholeAddressRule();
    void schemaListsEveryTable4ParameterWithDefault_data();
    void schemaListsEveryTable4ParameterWithDefault();
    void schemaCoversEveryGroupOfTheIssue();
    void everySchemaDefaultIsValid();
    void encodeSettingsBuildsOneSentencePerCommandInSafeOrder();
    void encodeSettingsRefusesBeforeBuilding_data();
    void encodeSettingsRefusesBeforeBuilding();
    void sentencesLongerThanTheDialectAllowsAreRefused();
    void encodeQueriesReadsBack();
    void extractSettingsReadsReplies();
    void cliSchemaListsEveryTable4Parameter();
    void cliEncodeSetAndQuery();
};

void TstNvsSchema::dialectRecordIsComplete() {
    const Dialect &d = nvs::dialect();
    QCOMPARE(d.id, std::string_view("nvs"));
    QCOMPARE(d.displayName, std::string_view("NVS NV08C-RTK"));
    QCOMPARE(d.defaultBaud, 115200);
    QCOMPARE(d.probeCommand, std::string_view("$PNVGVER*4E"));
    QCOMPARE(nvs::encodeVersionRequest().sentences.at(0), std::string(d.probeCommand));
    QVERIFY(d.extractSettings && d.ggaQuality);
    for (const SettingDef &def : d.settings) QVERIFY2(def.command, def.key.data());
    QVERIFY(!d.checksumOptional);
    QVERIFY(!d.commandNames.empty());
    QVERIFY(!d.replyRules.empty());
    const DialectRegistry reg = makeBuiltinRegistry();
    QCOMPARE(reg.find("nvs"), &d);
}

void TstNvsSchema::everyProprietaryAddressHasAWholeAddressRule() {
    // Table 3's proprietary messages.
    const char *addresses[] = {"PNVGVER", "PNVGNME", "PNVGRST", "PNVGRZA", "PNVGRZB", "PNVGBSS",
                               "PNVGTST", "PNVGCFG", "PNVGPPS", "PNVGIMU", "PNVGBRS", "PNVGBLS",
                               "PNVGVOG", "PNVGRTK", "PNVGIDL", "PNVGTME", "PNVGTMU", "PNVGTMC",
                               "PNVGSDP", "PNVGSDV", "PNVGSDH", "PNVGDOP"};
    const auto rules = nvs::dialect().rules;
    QCOMPARE(rules.size(), std::size(addresses));
    for (const char *a : addresses) {
        bool found = false;
        for (const auto &r : rules)
            if (r.address == a) {
                found = true;
                QCOMPARE(int(r.match), int(AddressMatch::Whole));
                QVERIFY(r.decode);
            }
        QVERIFY2(found, a);
    }
}

void TstNvsSchema::schemaListsEveryTable4ParameterWithDefault_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("defaultValue");
    const char *table4[][2] = {
            {"MODE", "2"},       {"PVTRATE", "5"},   {"SYSGPS", "1"},     {"SYSGLO", "1"},
            {"SYSSBAS", "1"},    {"ELGPS", "5"},     {"ELGLO", "5"},      {"ELSBAS", "5"},
            {"ELMASKA", "5"},    {"SNR", "33"},      {"SNRMASKA", "12"},  {"RTCMAGE", "45"},
            {"BASEID", "2"},     {"RTCMRATE", "1"},  {"BASEXYZ", ""},     {"BASEBLH", ""},
            {"BASETH", "500"},   {"BASENMEA", "0"},  {"AVGTIME", "30"},   {"AVGMODE", "0"},
            {"RAIM", "1"},       {"SFMODE", "0"},    {"SFTRS", "0.05"},   {"DPFMODE", "0"},
            {"VRSMODE", "0"},    {"ICBGLO", "0"},    {"ICBMODE", "2"},    {"ICBTIME", "20"},
            {"ICBMBGLO", "0"},   {"ICBMBMODE", "0"}, {"ICBMBTIME", "20"}, {"BASELINE", "0.0"},
            {"INITGPSWEEK", ""},
    };
    QCOMPARE(std::size(table4), std::size_t(33));
    for (const auto &row : table4) QTest::newRow(row[0]) << row[0] << row[1];
}

void TstNvsSchema::schemaListsEveryTable4ParameterWithDefault() {
    QFETCH(QString, name);
    QFETCH(QString, defaultValue);
    const std::string key = "rtk." + name.toStdString();
    const SettingDef *d = findSetting(nvs::settingsSchema(), key);
    QVERIFY2(d, key.c_str());
    QCOMPARE(QString::fromUtf8(d->defaultValue.data(), int(d->defaultValue.size())), defaultValue);
    QCOMPARE(d->group, std::string_view("RTK engine"));
    QVERIFY(!d->label.empty() && !d->help.empty() && !d->readBack.empty() && !d->write.empty());
    QCOMPARE(int(d->access), int(SettingAccess::ReadWrite));
    // The spec's own name finds it too.
    QCOMPARE(findSetting(nvs::settingsSchema(), name.toStdString()), d);
    QVERIFY(nvs::isRtkParameter(name.toStdString()));
}

void TstNvsSchema::schemaCoversEveryGroupOfTheIssue() {
    const char *keys[] = {"nmea.time_decimals", "nmea.position_decimals",
                          "nmea.talker_mode",   "port.COM1.baud",
                          "port.COM1.protocol", "port.COM2.baud",
                          "port.COM2.protocol", "port.USB.baud",
                          "port.USB.protocol",  "output.COM1",
                          "output.COM2",        "output.USB",
                          "pps.type",           "pps.mode",
                          "pps.reference",      "pps.adjust",
                          "pps.duration",       "pps.validity",
                          "pps.cable_delay",    "idl.mode",
                          "idl.stations"};
    for (const char *k : keys) QVERIFY2(findSetting(nvs::settingsSchema(), k), k);
    QSet<QString> seen;
    for (const auto &d : nvs::settingsSchema()) {
        const QString k = QString::fromUtf8(d.key.data(), int(d.key.size()));
        QVERIFY2(!seen.contains(k), qPrintable("duplicate key " + k));
        seen.insert(k);
        QVERIFY2(!d.label.empty() && !d.group.empty() && !d.help.empty(), qPrintable(k));
        QVERIFY2(!d.write.empty() && !d.readBack.empty(), qPrintable(k));
        if (d.type == SettingType::Enum) QVERIFY2(!d.options.empty(), qPrintable(k));
    }
    QCOMPARE(seen.size(), 33 + int(std::size(keys)));
}

void TstNvsSchema::everySchemaDefaultIsValid() {
    for (const auto &d : nvs::settingsSchema()) {
        if (d.defaultValue.empty() || d.type == SettingType::List) continue;
        const std::string err = validateSetting(d, d.defaultValue);
        QVERIFY2(err.empty(), err.c_str());
    }
}

void TstNvsSchema::encodeSettingsBuildsOneSentencePerCommandInSafeOrder() {
    const KeyValue values[] = {
            {"port.COM1.baud", "460800"},
            {"port.COM1.protocol", "1"},
            {"rtk.MODE", "1"},
            {"PVTRATE", "10"},
            {"pps.duration", "500"},
            {"output.COM2", "RMC:1;GSV:5"},
            {"nmea.time_decimals", "3"},
            {"nmea.position_decimals", "8"},
            {"idl.stations", "3:0.072;43"},
            {"idl.mode", "1"},
    };
    const auto r = encodeSettings(nvs::dialect(), std::span<const KeyValue>(values));
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(lines(r),
             QStringList({"$PNVGRTK,MODE,1,PVTRATE,10", "$PNVGIDL,MODE,1", "$PNVGIDL,CLEAR",
                          "$PNVGIDL,ADD,0003,0.0720", "$PNVGIDL,ADD,0043", "$PNVGPPS,,,,,500,,",
                          "$PNVGNME,3,8", "$PNVGRZB,PORT,2", "$PNVGRZB,PORT,2,RMC,1,GSV,5",
                          "$PNVGRZA,1,460800,1"}));
}

void TstNvsSchema::encodeSettingsRefusesBeforeBuilding_data() {
    test::addRefusedSettingColumns();
    textRow("unknown key", {"rtk.NOPE", "1", "rtk.NOPE"});
    textRow("PVTRATE 3", {"rtk.PVTRATE", "3", "1, 2, 5, 10"});
    textRow("baud alone", {"port.COM2.baud", "9600", "port.COM2.protocol"});
    textRow("NME alone", {"nmea.time_decimals", "3", "nmea.position_decimals"});
    textRow("output bad rate", {"output.COM1", "RMC:x", "output.COM1"});
    textRow("output rate 0", {"output.COM1", "RMC:0", ">= 1"});
    textRow("station bad", {"idl.stations", "abc", "idl.stations"});
    textRow("station id", {"idl.stations", "5000:0.1", "0..4095"});
    // The receiver keeps each station once (found by fuzz_settings_roundtrip: 40 twice was sent
    // and read back once).
    textRow("station twice", {"idl.stations", "85;40;84;40:0.1", "station 40 is listed twice"});
    textRow("PPS delay", {"pps.cable_delay", "10000", "0..9999"});
    // A number of 5,000 digits is a mistake, and would make a sentence no receiver reads.
    textRow("5000 digits", {"rtk.ICBGLO", "0." + QString(5000, '3'), "at most 32"});
}

void TstNvsSchema::encodeSettingsRefusesBeforeBuilding() {
    // A valid setting first: nothing at all may be built when a later one is refused.
    test::checkRefusedSetting([](const KeyValue &refused) {
        const KeyValue values[] = {{"rtk.MODE", "2"}, refused};
        return encodeSettings(nvs::dialect(), std::span<const KeyValue>(values));
    });
}

void TstNvsSchema::sentencesLongerThanTheDialectAllowsAreRefused() {
    const std::size_t max = Dialect{}.maxSentenceLength;
    QCOMPARE(max, std::size_t(82)); // NMEA 0183's limit, with the line end, unless a vendor says
    // The NV08C-RTK takes longer lines (revision 1.4), as a PNVGRTK setting many parameters is.
    QVERIFY(nvs::dialect().maxSentenceLength > max);
    EncodeResult fits;
    fits.sentences = {"$PNVGRTK", std::string(max - 2, 'x')};
    refuseLongSentences(fits, max);
    QVERIFY(fits.ok());
    QCOMPARE(fits.sentences.size(), std::size_t(2));
    EncodeResult over;
    over.sentences = {"$PNVGRTK", std::string(max - 1, 'x')};
    refuseLongSentences(over, max);
    QVERIFY(!over.ok());
    QVERIFY(over.sentences.empty()); // nothing is left to send
    QVERIFY2(QString::fromStdString(over.error).contains("83 characters"), over.error.c_str());
    QVERIFY(QString::fromStdString(over.error).contains("at most 82"));
}

void TstNvsSchema::encodeQueriesReadsBack() {
    const std::string keys[] = {"rtk.MODE", "BASEXYZ", "pps.type", "pps.duration", "idl.stations"};
    const auto r = encodeQueries(nvs::dialect(), std::span<const std::string>(keys));
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(lines(r), QStringList({"$PNVGRTK,MODE,BASEXYZ", "$PNVGPPS,,,,,,,", "$PNVGIDL,SHOW"}));
    const std::string writeOnly[] = {"port.COM1.baud"};
    const auto w = encodeQueries(nvs::dialect(), std::span<const std::string>(writeOnly));
    QVERIFY(!w.ok());
    QVERIFY(QString::fromStdString(w.error).contains("write-only"));
}

void TstNvsSchema::extractSettingsReadsReplies() {
    auto kv = extract("$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D");
    QCOMPARE(kv.size(), std::size_t(2));
    QCOMPARE(kv[0].key, std::string("rtk.MODE"));
    QCOMPARE(kv[0].value, std::string("1"));
    QCOMPARE(kv[1].key, std::string("rtk.BASEXYZ"));
    QCOMPARE(kv[1].value, std::string("4268995.2112,721584.9731,4668481.3737"));
    kv = extract("$PNVGPPS,P,S,U,1,1000,D,0*62");
    QCOMPARE(kv.size(), std::size_t(7));
    QCOMPARE(kv[4].key, std::string("pps.duration"));
    QCOMPARE(kv[4].value, std::string("1000"));
    kv = extract("$PNVGRZA,1,115200,1*6D");
    QCOMPARE(kv.size(), std::size_t(2));
    QCOMPARE(kv[0].key, std::string("port.COM1.baud"));
    QCOMPARE(kv[0].value, std::string("115200"));
    kv = extract("$PNVGIDL,MODE,1*7C");
    QCOMPARE(kv.size(), std::size_t(1));
    QCOMPARE(kv[0].key, std::string("idl.mode"));
    // Every extracted key is a schema key, and its value passes the schema's validation.
    for (const auto &k : extract("$PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040*04")) {
        QVERIFY(findSetting(nvs::settingsSchema(), k.key));
        QVERIFY(nvs::validateRtkValue("BASEBLH", k.value).empty());
    }
}

void TstNvsSchema::cliSchemaListsEveryTable4Parameter() {
    if (!QFileInfo::exists(cliPath())) QSKIP("gnss-cli not built");
    QProcess p;
    p.start(cliPath(), {"schema", "nvs"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 0);
    const auto arr = QJsonDocument::fromJson(p.readAllStandardOutput()).array();
    QVERIFY(!arr.isEmpty());
    QHash<QString, QJsonObject> byKey;
    for (const auto &v : arr) byKey.insert(v.toObject()["key"].toString(), v.toObject());
    for (auto name : nvs::rtkParameterNames()) {
        const QString key = "rtk." + QString::fromUtf8(name.data(), int(name.size()));
        QVERIFY2(byKey.contains(key), qPrintable(key));
        const auto def = findSetting(nvs::settingsSchema(), key.toStdString());
        QCOMPARE(byKey[key]["default"].toString(),
                 QString::fromUtf8(def->defaultValue.data(), int(def->defaultValue.size())));
    }
    QCOMPARE(byKey["rtk.PVTRATE"]["default"].toString(), QString("5"));
}

void TstNvsSchema::cliEncodeSetAndQuery() {
    if (!QFileInfo::exists(cliPath())) QSKIP("gnss-cli not built");
    QProcess p;
    p.start(cliPath(),
            {"encode", "nvs", "rtk.MODE=1", "BASEXYZ=4268995.2112,721584.9731,4668481.3737"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 0);
    QCOMPARE(QString::fromUtf8(p.readAllStandardOutput()).trimmed(),
             QString("$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D"));
    p.start(cliPath(), {"encode", "nvs", "--query", "rtk.BASEXYZ"});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 0);
    QVERIFY(QString::fromUtf8(p.readAllStandardOutput()).startsWith("$PNVGRTK,BASEXYZ*"));
    p.start(cliPath(), {"encode", "nvs", "rtk.PVTRATE=3"});
    QVERIFY(p.waitForFinished(30000));
    QVERIFY(p.exitCode() != 0);
    QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains("rtk.PVTRATE"));
    // Too long a value: a clear error and nothing printed to send.
    p.start(cliPath(), {"encode", "nvs", "rtk.ICBGLO=0." + QString(5000, '3')});
    QVERIFY(p.waitForFinished(30000));
    QVERIFY(p.exitCode() != 0);
    QVERIFY(p.readAllStandardOutput().isEmpty());
    QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains("5002 characters"));
}

QTEST_APPLESS_MAIN(TstNvsSchema)
#include "tst_nvs_schema.moc"
