// The settings engine against the in-process simulator, for each dialect: read everything,
// change every writable setting and verify it in the simulator and by read-back, a refused value
// reported, profiles carried back onto a changed receiver, save to flash across a power cycle,
// restore defaults, cancel.
#include "core/settings_plan.h"
#include "dialect_rows.h"
#include "engine_rig.h"

#include "config/presets.h"
#include "config/setting_values.h"
#include "geostar/sim/geostar_sim_receiver.h"
#include "nemerix/sim/nemerix_sim_receiver.h"
#include "nvs/sim/nvs_sim_receiver.h"
#include "vendor_test_rows.h"

#include <QTemporaryDir>

using namespace gnss;
using namespace gnss::config;
using namespace gnss::config::test;
using gnss::test::textRow;

namespace {

using Values = std::vector<KeyValue>;

// A new value for every writable setting (different from the simulator's defaults, and leaving
// the host's link in NMEA).
Values everySetting(const QString &dialect) {
    if (dialect == "nvs")
        return {{"rtk.MODE", "4"},
                {"rtk.PVTRATE", "10"},
                {"rtk.SYSGPS", "1"},
                {"rtk.SYSGLO", "0"},
                {"rtk.SYSSBAS", "0"},
                {"rtk.ELGPS", "10"},
                {"rtk.ELGLO", "11"},
                {"rtk.ELSBAS", "12"},
                {"rtk.ELMASKA", "7"},
                {"rtk.SNR", "30"},
                {"rtk.SNRMASKA", "15"},
                {"rtk.RTCMAGE", "60"},
                {"rtk.BASEID", "17"},
                {"rtk.RTCMRATE", "5"},
                {"rtk.BASEXYZ", "2850000.1234,2200000.5678,5250000.9012"},
                // The same point as BASEXYZ: the receiver keeps one antenna reference point.
                {"rtk.BASEBLH", "0.9728055654,0.6573892086,2356.7983"},
                {"rtk.BASETH", "250"},
                {"rtk.BASENMEA", "1"},
                {"rtk.AVGTIME", "45"},
                {"rtk.AVGMODE", "2"},
                {"rtk.RAIM", "0"},
                {"rtk.SFMODE", "2"},
                {"rtk.SFTRS", "0.1"},
                {"rtk.DPFMODE", "1"},
                {"rtk.VRSMODE", "1"},
                {"rtk.ICBGLO", "0.072"},
                {"rtk.ICBMODE", "1"},
                {"rtk.ICBTIME", "30"},
                {"rtk.ICBMBGLO", "-0.05"},
                {"rtk.ICBMBMODE", "2"},
                {"rtk.ICBMBTIME", "25"},
                {"rtk.BASELINE", "1.25"},
                {"rtk.INITGPSWEEK", "2300"},
                {"nmea.time_decimals", "3"},
                {"nmea.position_decimals", "8"},
                {"nmea.talker_mode", "1"},
                {"port.COM1.baud", "57600"},
                {"port.COM1.protocol", "1"},
                {"port.COM2.baud", "38400"},
                {"port.COM2.protocol", "7"},
                {"port.USB.baud", "230400"},
                {"port.USB.protocol", "0"},
                {"output.COM1", "GGA:1;RMC:1;GSV:5"},
                {"output.COM2", "GGA:1"},
                {"output.USB", "RMC:2;ZDA:10"},
                {"pps.type", "A"},
                {"pps.mode", "I"},
                {"pps.reference", "G"},
                {"pps.adjust", "0"},
                {"pps.duration", "500"},
                {"pps.validity", "E"},
                {"pps.cable_delay", "120"},
                {"idl.mode", "1"},
                {"idl.stations", "3:0.0720;43:0.0000"}};
    if (dialect == "geostar")
        return {{"output.GGA", "0"},   {"output.GLL", "1"},  {"output.GSA", "0"},
                {"output.GSV", "0"},   {"output.RMC", "1"},  {"output.VTG", "1"},
                {"output.ZDA", "0"},   {"output.DTM", "0"},  {"output.RLM", "1"},
                {"output.NMEAV", "4"}, {"output.RATE", "5"}, {"power.PSM", "1"},
                {"nav.ELEV", "10"},    {"nav.DAT", "P90"},   {"nav.NVS", "GPS"},
                {"port.BDR", "57600"}, {"port.STOP", "2"}};
    return {{"serial.protocol", "0"},
            {"serial.baud", "19200"},
            {"serial.parity", "0"},
            {"rate.GGA", "2"},
            {"rate.GLL", "1"},
            {"rate.GSA", "0"},
            {"rate.GSV", "5"},
            {"rate.RMC", "2"},
            {"rate.VTG", "0"},
            {"rate.ZDA", "1"},
            {"output.sequence", "RMC;GGA;GSV;GLL;ZDA"},
            {"nmrx.300", "0"},
            {"nmrx.301", "0"},
            {"nmrx.302", "0"},
            {"nmrx.303", "2"},
            {"nmrx.304", "0"},
            {"datum.correction", "0"},
            {"datum.mapDatum", "500"},
            {"datum.dx", "10"},
            {"datum.dy", "-20"},
            {"datum.dz", "30"},
            {"datum.inverseFlattening", "298.5"},
            {"datum.semiMajorAxis", "6378000"},
            {"fix.timeZone", "2:30"},
            {"fix.maxPdop", "8.5"},
            {"fix.maxHdop", "4.5"},
            {"fix.maxVdop", "6.5"},
            {"fix.minSnr", "30"},
            {"fix.minElevation", "10"},
            {"fix.noiseFloor", "700"},
            {"fix.altitude2d", "150"},
            {"fix.maxAltitude", "20000"},
            {"nav.mode", "4"},
            {"nav.dynamics", "1"},
            {"nav.channels", "14"},
            {"power.mode", "1"},
            {"power.offPeriod", "7"}};
}

// Readable settings the simulator leaves unreported by default (NVS: an empty station list is
// answered "$PNVGIDL,0", which carries no station).
bool unreportedByDefault(const std::string &key) {
    return key == "idl.stations";
}

void addDialectRows() {
    gnss::test::addSettingsDialectRows();
}

} // namespace

class TstSettingsEngine : public QObject {
    Q_OBJECT
private slots:
    void readAllReportsEveryReadableSetting_data() { addDialectRows(); }
    void readAllReportsEveryReadableSetting() {
        QFETCH(QString, dialect);
        EngineRig rig(dialect);
        QVERIFY(rig.opened);
        const auto r = rig.readAll();
        QVERIFY2(r.ok(), describe(r));
        for (const auto &def : rig.dialect->settings) {
            const std::string key(def.key);
            if (isAction(def)) continue;
            if (def.access == SettingAccess::WriteOnly) {
                QCOMPARE(int(rig.engine.state(key)), int(ValueState::WriteOnly));
                QCOMPARE(rig.engine.displayValue(key), QString("unknown (write-only)"));
            } else if (!unreportedByDefault(key)) {
                QVERIFY2(rig.engine.state(key) == ValueState::Reported, def.key.data());
            }
        }
        QVERIFY2(!rig.engine.identity().firmware.empty() || !rig.engine.identity().model.empty(),
                 "the identity was read with the settings");
    }

    void changingEverySettingIsAppliedAndVerified_data() { addDialectRows(); }
    void changingEverySettingIsAppliedAndVerified() {
        QFETCH(QString, dialect);
        EngineRig rig(dialect);
        QVERIFY(rig.opened);
        QVERIFY2(rig.readAll().ok(), describe(rig.engine.lastReport()));
        const Values values = everySetting(dialect);
        // Every writable setting of the schema is in the list.
        for (const auto &def : rig.dialect->settings) {
            if (!isWritable(def)) continue;
            bool listed = false;
            for (const auto &kv : values) listed = listed || kv.key == def.key;
            QVERIFY2(listed, def.key.data());
        }
        const auto r = rig.apply(values);
        VERIFY_REPORT(r);
        for (const auto &c : r.checks) QVERIFY2(isGood(c.verdict), describe(r));

        // The simulator's state.
        if (dialect == "nvs") {
            const auto *rx = static_cast<sim::NvsReceiver *>(rig.sim.receiver());
            const auto &s = rx->settings();
            // Items of a list setting ("RMC:1;GSV:5").
            const auto items = [&](const char *key) {
                const std::string &v = s.value(key);
                return v.empty() ? 0 : int(std::count(v.begin(), v.end(), ';')) + 1;
            };
            QCOMPARE(s.value("rtk.MODE"), std::string("4"));
            QCOMPARE(s.value("rtk.ELGLO"), std::string("11"));
            QCOMPARE(s.integer("nmea.time_decimals"), 3LL);
            QCOMPARE(s.integer("nmea.position_decimals"), 8LL);
            QCOMPARE(s.integer("nmea.talker_mode"), 1LL);
            QCOMPARE(s.integer("port.COM1.baud"), 57600LL);
            QCOMPARE(s.integer("port.COM2.baud"), 38400LL);
            QCOMPARE(s.integer("port.COM2.protocol"), 7LL);
            QCOMPARE(s.integer("port.USB.protocol"), 0LL);
            QCOMPARE(items("output.COM2"), 1);
            QCOMPARE(items("output.USB"), 2);
            QCOMPARE(s.value("pps.type"), std::string("A"));
            QCOMPARE(s.integer("pps.cable_delay"), 120LL);
            QCOMPARE(s.integer("idl.mode"), 1LL);
            QCOMPARE(items("idl.stations"), 2);
            QCOMPARE(rig.sim.baud(), 57600); // the link followed COM1's new speed
        } else if (dialect == "geostar") {
            const auto *rx = static_cast<sim::GeoStarReceiver *>(rig.sim.receiver());
            const auto &s = rx->settings();
            QCOMPARE(s.integer("nav.ELEV"), 10LL);
            QCOMPARE(s.integer("port.BDR"), 57600LL);
            QCOMPARE(s.integer("port.STOP"), 2LL);
            QCOMPARE(s.value("nav.DAT"), std::string("P90"));
            QCOMPARE(s.value("nav.NVS"), std::string("GPS"));
            QCOMPARE(s.integer("output.RATE"), 5LL);
            QCOMPARE(s.integer("output.NMEAV"), 4LL);
            QCOMPARE(s.value("power.PSM"), std::string("1"));
            QCOMPARE(rig.sim.baud(), 57600);
        } else {
            const auto *rx = static_cast<sim::NemerixReceiver *>(rig.sim.receiver());
            const auto &s = rx->settings();
            QCOMPARE(s.integer("serial.baud"), 19200LL);
            QCOMPARE(s.real("fix.maxVdop"), 6.5);
            QCOMPARE(s.integer("fix.maxAltitude"), 20000LL);
            QCOMPARE(s.integer("nav.mode"), 4LL);
            QCOMPARE(s.integer("nav.dynamics"), 1LL);
            QCOMPARE(s.integer("nav.channels"), 14LL);
            QCOMPARE(s.integer("power.mode"), 1LL);
            QCOMPARE(s.integer("power.offPeriod"), 7LL);
            QCOMPARE(s.integer("nmrx.303"), 2LL);
            QCOMPARE(s.value("output.sequence"), std::string("RMC;GGA;GSV;GLL;ZDA"));
            QCOMPARE(s.integer("datum.mapDatum"), 500LL);
            QCOMPARE(s.integer("datum.dz"), 30LL);
            QCOMPARE(rig.sim.baud(), 19200);
        }

        // A fresh read shows every readable value as set; applying again sends nothing.
        rig.engine.forget();
        QVERIFY2(rig.readAll().ok(), describe(rig.engine.lastReport()));
        for (const auto &kv : values) {
            const SettingDef *def = findSetting(rig.dialect->settings, kv.key);
            if (!isReadable(*def)) continue;
            const auto got = rig.engine.receiverValue(kv.key);
            QVERIFY2(got && sameValue(*def, kv.value, *got),
                     qPrintable(QString::fromStdString(kv.key + " read back as " +
                                                       got.value_or("nothing"))));
        }
    }

    void aValueOutOfRangeIsRefusedBeforeAnythingIsSent() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        const auto before = rig.queue.history().size();
        const auto r = rig.apply({{"rtk.ELGPS", "95"}, {"rtk.ELGLO", "10"}});
        QVERIFY(!r.ok());
        QVERIFY2(r.error.contains("ELGPS"), qPrintable(r.error));
        QCOMPARE(rig.queue.history().size(), before);
        QVERIFY(!rig.engine.isBusy());
    }

    void aValueTheReceiverRefusesIsReported() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        // 5000 baud is in the schema's range but not a rate the receiver has: it answers with
        // the speed in force.
        const auto r = rig.apply({{"port.COM2.baud", "5000"}, {"port.COM2.protocol", "1"}});
        QVERIFY(!r.ok());
        QCOMPARE(r.failedCommands(), 1);
        QCOMPARE(int(r.commands.first().outcome), int(link::CommandOutcome::Refused));
        bool marked = false;
        for (const auto &c : r.checks)
            if (c.key == "port.COM2.baud") {
                QCOMPARE(int(c.verdict), int(Verdict::NotTaken));
                QCOMPARE(c.reported, std::string("115200"));
                marked = true;
            }
        QVERIFY2(marked, describe(r));
    }

    void aSettingWrittenWithItsPartnerTakesThePartnersKnownValue() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        const auto r = rig.apply({{"port.USB.baud", "230400"}});
        QVERIFY2(r.ok(), describe(r));
        QCOMPARE(int(r.companions.size()), 1);
        QCOMPARE(r.companions.front().key, std::string("port.USB.protocol"));
        QVERIFY(r.commands.first().sentence.startsWith("$PNVGRZA,3,230400,1*"));
    }

    void aProfileCarriesTheSettingsBack_data() { addDialectRows(); }
    void aProfileCarriesTheSettingsBack() {
        QFETCH(QString, dialect);
        EngineRig rig(dialect);
        QVERIFY(rig.opened);
        Values first, second;
        if (dialect == "nvs") {
            first = {{"rtk.ELGPS", "12"},
                     {"rtk.SFTRS", "0.2"},
                     {"nmea.time_decimals", "1"},
                     {"nmea.position_decimals", "6"},
                     {"pps.duration", "200"}};
            second = {{"rtk.ELGPS", "20"},
                      {"rtk.SFTRS", "0.3"},
                      {"nmea.time_decimals", "4"},
                      {"nmea.position_decimals", "5"},
                      {"pps.duration", "300"}};
        } else if (dialect == "geostar") {
            first = {{"output.RATE", "2"}, {"nav.ELEV", "7"}, {"output.VTG", "1"}};
            second = {{"output.RATE", "10"}, {"nav.ELEV", "12"}, {"output.VTG", "0"}};
        } else {
            first = {{"fix.minSnr", "33"}, {"fix.maxVdop", "4"}, {"rate.GSV", "4"}};
            second = {{"fix.minSnr", "22"}, {"fix.maxVdop", "7"}, {"rate.GSV", "1"}};
        }
        QVERIFY2(rig.readAll().ok(), describe(rig.engine.lastReport()));
        QVERIFY2(rig.apply(first).ok(), describe(rig.engine.lastReport()));
        QVERIFY2(rig.readAll().ok(), describe(rig.engine.lastReport()));

        QTemporaryDir dir;
        const QString path = dir.filePath("receiver.json");
        QString error;
        QVERIFY2(saveProfile(path, rig.engine.exportProfile(), &error), qPrintable(error));
        Profile profile;
        QVERIFY2(loadProfile(path, profile, &error, rig.dialect), qPrintable(error));
        QCOMPARE(QString::fromStdString(profile.dialect), dialect);
        QVERIFY(rig.engine.diff(profile).empty());

        // Another receiver (the same one, changed), then the profile applied onto it.
        QVERIFY2(rig.apply(second).ok(), describe(rig.engine.lastReport()));
        QVERIFY(!rig.engine.diff(profile).empty());
        const auto r = rig.run([&] { return rig.engine.applyProfile(profile); });
        QVERIFY2(r.ok(), describe(r));
        rig.engine.forget();
        QVERIFY2(rig.readAll().ok(), describe(rig.engine.lastReport()));
        // Readable values come back from the receiver; write-only ones from what was set.
        for (const auto &kv : first) {
            const SettingDef *def = findSetting(rig.dialect->settings, kv.key);
            if (!isReadable(*def)) continue;
            const auto got = rig.engine.receiverValue(kv.key);
            QVERIFY2(got && sameValue(*def, kv.value, *got), kv.key.c_str());
        }
        if (dialect == "nemerix")
            QCOMPARE(static_cast<sim::NemerixReceiver *>(rig.sim.receiver())
                             ->settings()
                             .real("fix.maxVdop"),
                     4.0);
        if (dialect == "geostar")
            QCOMPARE(static_cast<sim::GeoStarReceiver *>(rig.sim.receiver())
                             ->settings()
                             .integer("nav.ELEV"),
                     7LL);
        if (dialect == "nvs")
            QCOMPARE(static_cast<sim::NvsReceiver *>(rig.sim.receiver())
                             ->settings()
                             .integer("nmea.time_decimals"),
                     1LL);
    }

    void saveToFlashSurvivesAPowerCycle_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        textRow("nvs", {"nvs", "rtk.ELGPS", "15"});
        textRow("geostar", {"geostar", "output.RATE", "2"});
    }
    void saveToFlashSurvivesAPowerCycle() {
        QFETCH(QString, dialect);
        QFETCH(QString, key);
        QFETCH(QString, value);
        EngineRig rig(dialect);
        QVERIFY(rig.opened);
        QVERIFY2(rig.apply({{key.toStdString(), value.toStdString()}}).ok(),
                 describe(rig.engine.lastReport()));
        const auto saved = rig.run([&] { return rig.engine.runAction(Action::SaveToFlash); });
        QVERIFY2(saved.ok(), describe(saved));
        rig.sim.receiver()->powerCycle();
        rig.engine.forget();
        QVERIFY2(rig.run([&] { return rig.engine.read({key.toStdString()}); }).ok(),
                 describe(rig.engine.lastReport()));
        QCOMPARE(QString::fromStdString(rig.engine.receiverValue(key.toStdString()).value_or("")),
                 value);
    }

    void withoutSaveAPowerCycleForgetsTheChange() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        QVERIFY(rig.apply({{"rtk.ELGPS", "15"}}).ok());
        rig.sim.receiver()->powerCycle();
        rig.engine.forget();
        QVERIFY(rig.run([&] { return rig.engine.read({"rtk.ELGPS"}); }).ok());
        QCOMPARE(rig.engine.receiverValue("rtk.ELGPS").value_or(""), std::string("5"));
    }

    void restoreDefaultsBringsTheFactoryValuesBack() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        QVERIFY(rig.apply({{"rtk.ELGPS", "15"}}).ok());
        QVERIFY(rig.run([&] { return rig.engine.runAction(Action::SaveToFlash); }).ok());
        const auto r = rig.run([&] { return rig.engine.runAction(Action::RestoreDefaults); });
        QVERIFY2(r.ok(), describe(r));
        QCOMPARE(int(rig.engine.state("rtk.ELGPS")), int(ValueState::NotRead));
        QVERIFY(rig.run([&] { return rig.engine.read({"rtk.ELGPS"}); }).ok());
        QCOMPARE(rig.engine.receiverValue("rtk.ELGPS").value_or(""), std::string("5"));
    }

    void actionsAreOfferedAsTheDialectHasThem() {
        EngineRig nemerix("nemerix");
        const auto actions = nemerix.engine.availableActions();
        QVERIFY(std::find(actions.begin(), actions.end(), Action::SaveToFlash) == actions.end());
        QVERIFY(std::find(actions.begin(), actions.end(), Action::HotStart) != actions.end());
        const auto r = nemerix.run([&] { return nemerix.engine.runAction(Action::SaveToFlash); });
        QVERIFY(!r.ok());
        QVERIFY2(r.error.contains("save"), qPrintable(r.error));
        const auto cold = nemerix.run([&] { return nemerix.engine.runAction(Action::ColdStart); });
        QVERIFY2(cold.ok(), describe(cold));
        QCOMPARE(cold.commands.first().sentence.left(15), QString("$PNMRX111,COLD*"));
    }

    void aReadCanBeCancelled() {
        EngineRig rig("nvs");
        QVERIFY(rig.opened);
        const auto r = rig.run([&] {
            const bool started = rig.engine.read();
            rig.engine.cancel();
            return started;
        });
        QVERIFY(r.cancelled);
        QVERIFY(!rig.engine.isBusy());
    }

    void presetsAreValidSettingsOfTheirDialects() {
        for (const Dialect *d : registry().dialects()) {
            for (const Preset &p : d->presets) {
                const auto values = presetValues(p);
                for (const auto &kv : values) {
                    const SettingDef *def = findSetting(d->settings, kv.key);
                    QVERIFY2(def && isWritable(*def), kv.key.c_str());
                }
                const EncodeResult r = encodeSettings(*d, values);
                QVERIFY2(r.ok(), r.error.c_str());
            }
        }
        QCOMPARE(int(registry().find("nvs")->presets.size()), 3);
        QCOMPARE(int(registry().find("geostar")->presets.size()), 1);
        QCOMPARE(int(registry().find("nemerix")->presets.size()), 1);
    }

    void aPresetIsAppliedLikeAnyChange() {
        EngineRig rig("geostar");
        QVERIFY(rig.opened);
        const auto r = rig.apply(presetValues(registry().find("geostar")->presets.front()));
        QVERIFY2(r.ok(), describe(r));
        const auto *rx = static_cast<sim::GeoStarReceiver *>(rig.sim.receiver());
        QCOMPARE(rx->settings().integer("output.NMEAV"), 4LL);
    }
};

QTEST_GUILESS_MAIN(TstSettingsEngine)
#include "tst_settings_engine.moc"
