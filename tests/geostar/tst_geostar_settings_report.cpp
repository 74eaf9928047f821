// The settings RQUERY and NQUERY report, both ways (geostar_settings_report.cpp): every value a
// reply can report, written into the reply (reportSettings), encoded, decoded and read back
// (extractSettings) is the value written; a decoded set command carries the setting and value of
// its row of the command table (what the simulator applies to its store), actions and queries
// none; a value the schema refuses leaves the reply as it was.
#include "builtin/dialects.h"
#include "core/setting_command.h"
#include "core/stream_decoder.h"
#include "decode_helper.h"
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_schema.h"

#include <QTest>

using namespace gnss;
using namespace gnss::geostar;

namespace {

// Decodes `line` with the geostar dialect and collects what extractSettings reads from it.
std::vector<KeyValue> extracted(const std::string &line) {
    return gnss::test::extractedSettings("geostar", line);
}

std::string only(const EncodeResult &r) {
    return r.ok() && r.sentences.size() == 1 ? r.sentences.front() : std::string();
}

// Every value each readable row accepts (booleans 0/1, each option of an enumeration).
std::vector<std::string> valuesOf(const SettingDef &d) {
    if (d.type == SettingType::Bool) return {"0", "1"};
    std::vector<std::string> v;
    for (const SettingOption &o : d.options) v.emplace_back(o.value);
    return v;
}

} // namespace

class TstGeostarSettingsReport : public QObject {
    Q_OBJECT
private slots:
    void everyReportedValueComesBackThroughTheReplies_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        int rows = 0;
        for (const SettingDef &d : settingsSchema()) {
            if (!d.command || !d.command->read || d.access == SettingAccess::WriteOnly) continue;
            for (const std::string &v : valuesOf(d)) {
                QTest::addRow("%s=%s", std::string(d.key).c_str(), v.c_str())
                        << QString::fromUtf8(d.key.data(), int(d.key.size()))
                        << QString::fromStdString(v);
                ++rows;
            }
        }
        // 9 outputs (2 values), NMEA version 2, rate 4, power saving 2, datum 3, systems 3.
        QCOMPARE(rows, 9 * 2 + 2 + 4 + 2 + 3 + 3);
    }
    void everyReportedValueComesBackThroughTheReplies() {
        QFETCH(QString, key);
        QFETCH(QString, value);
        const SettingValues values{{key.toStdString(), value.toStdString()}};
        Rquery q;
        q.receiverName = "GEOS-5";
        q.firmware = "V.5.102";
        Nquery n;
        n.port = 1;
        n.codes.fill('0');
        n.codeCount = Nquery::kMessages;
        QVERIFY(reportSettings(values, q).empty());
        QVERIFY(reportSettings(values, n).empty());
        int found = 0;
        for (const std::string &line : {only(encodeRquery(q)), only(encodeNquery(n))}) {
            QVERIFY(!line.empty());
            for (const KeyValue &kv : extracted(line)) {
                if (kv.key != key.toStdString()) continue;
                QCOMPARE(QString::fromStdString(kv.value), value);
                ++found;
            }
        }
        QVERIFY2(found > 0, "no reply reports it");
    }

    void aSetCommandCarriesItsSetting_data() {
        QTest::addColumn<QString>("text");
        for (const CommandDef &c : commands())
            QTest::newRow(std::string(c.text).c_str())
                    << QString::fromUtf8(c.text.data(), int(c.text.size()));
    }
    void aSetCommandCarriesItsSetting() {
        QFETCH(QString, text);
        const CommandDef *c = findCommand(text.toStdString());
        QVERIFY(c);
        const auto kv = extracted(encodeCommand(*c));
        if (c->settingKey.empty() || c->settingKey.starts_with("action.")) {
            QVERIFY(kv.empty()); // queries and actions set nothing a reply reports
            return;
        }
        QCOMPARE(kv.size(), std::size_t(1));
        QCOMPARE(kv.front().key, std::string(c->settingKey));
        QCOMPARE(kv.front().value, std::string(c->value));
        // And the store of a receiver takes it as the schema reads it.
        const SettingDef *def = findSetting(settingsSchema(), kv.front().key);
        QVERIFY(def && def->command && def->command->validate);
        QVERIFY(def->command->validate(*def, kv.front().value).empty());
    }

    void messagesOnKeepTheirCodeMessagesOffGetZero() {
        Nquery n;
        n.codes.fill('\0');
        n.codes[3] = '1'; // GSV once a second, as the receiver chooses
        n.codes[7] = '2'; // ZDA, to be switched off
        n.codes[6] = '3'; // the unknown position: no setting reports it
        const SettingValues values{{"output.GSV", "1"},
                                   {"output.GGA", "1"},
                                   {"output.ZDA", "0"},
                                   {"output.RATE", "10"},
                                   {"output.NMEAV", "4"}};
        QVERIFY(reportSettings(values, n).empty());
        QCOMPARE(n.codes[3], '1');
        QCOMPARE(n.codes[0], 'R'); // on, with no code of its own: at the output rate
        QCOMPARE(n.codes[7], '0');
        QCOMPARE(n.codes[6], '3');
        QCOMPARE(n.codes[1], '\0'); // GLL not given: as it was
        QCOMPARE(n.rateCode, std::optional<int>(0));
        QCOMPARE(n.nmeaVersion, std::optional<int>(4));
        QCOMPARE(n.codeCount, std::size_t(8));
    }

    void aValueTheSchemaRefusesLeavesTheReplyAsItWas() {
        Nquery n;
        n.rateCode = 3;
        const Refusal why = reportSettings({{"output.GGA", "1"}, {"output.RATE", "3"}}, n);
        QVERIFY(!why.empty() && why.form);
        QVERIFY2(why.text.find("output.RATE") != std::string::npos, why.text.c_str());
        QCOMPARE(n.rateCode, std::optional<int>(3));
        QCOMPARE(n.codes[0], '\0');
        Rquery q;
        QVERIFY(!reportSettings({{"power.PSM", "1"}, {"nav.DAT", "XYZ"}}, q).empty());
        QVERIFY(!q.config1.powerSavingEnabled);
        QCOMPARE(q.config2.datumCode, 0);
    }
};

QTEST_APPLESS_MAIN(TstGeostarSettingsReport)
#include "tst_geostar_settings_report.moc"
