// The simulator's settings store: the schema's defaults, values the schema refuses kept out,
// commands applied through the dialect's own decoding, reports in the command's form, flash.
#include "sim/settings_store.h"

#include "builtin/dialects.h"
#include "core/stream_decoder.h"
#include "nvs/nvs_dialect.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;

namespace {

// Applies one line as the simulated receiver would: decoded by the dialect, then stored.
std::vector<std::string> applyLine(SettingsStore &store, const DialectRegistry &registry,
                                   const std::string &line) {
    DecoderOptions o;
    o.dialect = "nvs";
    StreamDecoder decoder(registry, o);
    std::vector<std::string> changed;
    decoder.decodeLine(line, [&](const SentenceEvent &ev) {
        if (ev.message) changed = store.apply(*ev.message);
    });
    return changed;
}

} // namespace

class TstSimSettingsStore : public QObject {
    Q_OBJECT
    const DialectRegistry registry_ = makeBuiltinRegistry();

private slots:
    void startsAtTheSchemaDefaults() {
        SettingsStore s(nvs::dialect());
        for (const SettingDef &def : nvs::dialect().settings)
            QCOMPARE(s.value(def.key), std::string(def.defaultValue));
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("5"));
        QCOMPARE(s.integer("rtk.MODE"), 2LL);
        QCOMPARE(s.value("no.such.key"), std::string());
    }

    void keepsOutWhatTheSchemaRefuses() {
        SettingsStore s(nvs::dialect());
        QVERIFY(s.set("rtk.PVTRATE", "10"));
        QVERIFY(!s.set("rtk.PVTRATE", "7")); // not one of 1, 2, 5, 10
        QVERIFY(!s.set("rtk.ELGPS", "91"));  // out of range
        QVERIFY(!s.set("no.such.key", "1"));
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("10"));
    }

    void appliesADecodedCommandAndSaysWhatChanged() {
        SettingsStore s(nvs::dialect());
        const auto changed = applyLine(s, registry_, "$PNVGRTK,PVTRATE,10,ELGPS,12*5D");
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("10"));
        QCOMPARE(s.value("rtk.ELGPS"), std::string("12"));
        QCOMPARE(changed, (std::vector<std::string>{"rtk.PVTRATE", "rtk.ELGPS"}));
        // A value the receiver does not take: the one in force stays.
        QVERIFY(applyLine(s, registry_, "$PNVGRTK,PVTRATE,3*21").empty());
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("10"));
    }

    void reportsInTheCommandsOwnForm() {
        SettingsStore s(nvs::dialect());
        QVERIFY(s.set("rtk.MODE", "1"));
        const std::vector<std::string> keys{"rtk.MODE", "rtk.PVTRATE"};
        const EncodeResult r = s.report(keys);
        QVERIFY2(r.ok(), r.error.c_str());
        QCOMPARE(r.sentences.size(), std::size_t(1));
        QVERIFY2(r.sentences.front().starts_with("$PNVGRTK,MODE,1,PVTRATE,5*"),
                 r.sentences.front().c_str());
    }

    void flashKeepsWhatWasSaved() {
        SettingsStore s(nvs::dialect());
        QVERIFY(s.set("rtk.PVTRATE", "10"));
        s.save();
        QVERIFY(s.set("rtk.PVTRATE", "1"));
        s.restore();
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("10"));
        s.saveDefaults();
        s.restore();
        QCOMPARE(s.value("rtk.PVTRATE"), std::string("5"));
        s.seed("rtk.INITGPSWEEK", "2048");
        s.saveDefaults();
        s.restore();
        QCOMPARE(s.value("rtk.INITGPSWEEK"), std::string("2048"));
    }
};

QTEST_APPLESS_MAIN(TstSimSettingsStore)
#include "tst_sim_settings_store.moc"
