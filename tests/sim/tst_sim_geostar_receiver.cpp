// The simulated GeoS-5M, in simulated time: default output (the spec's NQUERY example), every
// section 4 command's reply or effect, RQUERY words read back with the geostar decoder, flash
// persistence across a power cycle, v2.x / v4.10 numbering, baud switch; every set command lands
// in the settings store and reads back through the query that reports it.
#include "builtin/simulators.h"
#include "geostar/sim/geostar_sim_receiver.h"
#include "sim_output.h"
#include "sim_receiver.h"

#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "core/settings_plan.h"
#include "geostar/geostar_commands.h"
#include "geostar/geostar_messages.h"
#include "geostar/geostar_schema.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;
using gnss::test::summarize;

namespace {

std::unique_ptr<GeoStarReceiver> makeGeoStar(std::uint32_t seed = 1) {
    return gnss::test::makeReceiverAs<GeoStarReceiver>("geostar", seed);
}

void command(Receiver &rx, std::string_view text) {
    rx.receive(buildSentence("GPSGG," + std::string(text)) + "\r\n");
}

struct Decoded {
    std::optional<geostar::StatusWord> status;
    std::optional<geostar::ConfigRegister1> config1;
    std::optional<geostar::ConfigRegister2> config2;
    std::optional<std::string> nquery; // the reply line
    int rqueries = 0, nqueries = 0;
};

// The last RQUERY/NQUERY replies in `out`, decoded with the geostar decoder.
Decoded replies(const std::string &out) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    DecoderOptions o;
    o.dialect = "geostar";
    StreamDecoder d(registry, o);
    Decoded r;
    d.feed(out, [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        if (const auto *q = message_cast<geostar::Rquery>(*ev.message)) {
            r.status = q->status;
            r.config1 = q->config1;
            r.config2 = q->config2;
            ++r.rqueries;
        } else if (message_cast<geostar::Nquery>(*ev.message)) {
            r.nquery = std::string(ev.sentence.line());
            ++r.nqueries;
        }
    });
    return r;
}

Decoded query(Receiver &rx) {
    rx.takeOutput();
    command(rx, "RQUERY");
    command(rx, "NQUERY");
    rx.advance(0.01);
    return replies(rx.takeOutput());
}

} // namespace

class TstSimGeoStarReceiver : public QObject {
    Q_OBJECT
private slots:
    void defaultOutputIsTheSpecsNqueryExampleAtOneHertz() {
        auto rx = makeGeoStar();
        QCOMPARE(rx->baud(), 115200);
        QCOMPARE(rx->epochInterval(), 1.0);
        rx->advance(4.5); // epochs 0..4
        const std::string out = rx->takeOutput();
        const auto s = summarize(out, "geostar");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        QCOMPARE(s.count("GGA"), 5);
        QCOMPARE(s.count("ZDA"), 5);
        QCOMPARE(s.count("DTM"), 5);
        QVERIFY(s.count("GSA") >= 5 && s.count("GSV") >= 5);
        for (auto t : {"RMC", "VTG", "GLL", "GNS", "RLM"}) QVERIFY2(!s.count(t), t);
        // Power-on: one RQUERY and one NQUERY, the NQUERY the spec's own example.
        const auto r = replies(out);
        QCOMPARE(r.rqueries, 1);
        QCOMPARE(r.nqueries, 1);
        QCOMPARE(QString::fromStdString(*r.nquery),
                 QStringLiteral("$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71"));
    }
    void rqueryWordsReflectTheState() {
        auto rx = makeGeoStar();
        auto r = query(*rx);
        QVERIFY(r.status && r.config1 && r.config2);
        QVERIFY(r.status->active && r.status->backupRamOk && r.status->rtcOk && r.status->pllOk);
        QVERIFY(!r.status->solutionAvailable);
        QVERIFY(!r.status->gpsAlmanac);
        QVERIFY(r.status->antenna == geostar::AntennaState::Ok);
        QVERIFY(r.config1->gps && r.config1->glonass && r.config1->galileo && r.config1->sbas);
        QCOMPARE(r.config1->rateHz, 1);
        QVERIFY(!r.config1->powerSavingEnabled);
        QCOMPARE(r.config2->receiverType(), std::string_view("GeoS-5M"));
        QCOMPARE(r.config2->datumName(), std::string_view("WGS-84"));
        QCOMPARE(r.status->raw & geostar::StatusWord::kReservedMask, 0u);
        QCOMPARE(r.config1->raw & geostar::ConfigRegister1::kReservedMask, 0u);
        QCOMPARE(r.config2->raw & geostar::ConfigRegister2::kReservedMask, 0u);
        rx->advance(40); // fix, then SBAS corrections, almanacs complete
        r = query(*rx);
        QVERIFY(r.status->solutionAvailable && r.status->validSinceStart);
        QVERIFY(r.status->sbasCorrectionsUsed && r.status->differential);
        QVERIFY(r.status->gpsAlmanac && r.status->glonassAlmanac && r.status->galileoAlmanac);
        QVERIFY(r.status->timeFromNavMessage && r.status->dateFromNavMessage);
    }
    void everyCommandIsHandled_data() {
        QTest::addColumn<QString>("text");
        for (const geostar::CommandDef &c : geostar::commands())
            QTest::newRow(std::string(c.text).c_str())
                    << QString::fromUtf8(c.text.data(), c.text.size());
    }
    void everyCommandIsHandled() {
        QFETCH(QString, text);
        const std::string t = text.toStdString();
        const geostar::CommandDef *def = geostar::findCommand(t);
        QVERIFY(def);
        auto rx = makeGeoStar();
        rx->advance(35.5); // fixed, tracking, almanacs complete
        rx->takeOutput();
        command(*rx, t);
        rx->advance(0.01);
        const std::string reply = rx->takeOutput();
        const auto r = replies(reply);
        // Only the two queries are answered (reply rules: no other acknowledgement).
        QCOMPARE(r.rqueries, t == "RQUERY" ? 1 : 0);
        QCOMPARE(r.nqueries, t == "NQUERY" ? 1 : 0);
        if (t == "RQUERY" || t == "NQUERY") return;
        const std::string key(def->settingKey), value(def->value);
        const auto &st = rx->settings();
        if (key == "port.BDR") {
            QCOMPARE(rx->baud(), std::stoi(value));
            rx->setLineBaud(std::stoi(value));
        }
        if (t == "SWPROT") {
            rx->advance(3);
            QCOMPARE(rx->takeOutput().size(), std::size_t(0)); // NMEA off
            rx->powerCycle();
            rx->advance(1.5);
            QVERIFY(summarize(rx->takeOutput(), "geostar").count("GGA") > 0);
            return;
        }
        if (def->effect == CommandEffect::ResetsReceiver) {
            rx->advance(1.0);
            QCOMPARE(rx->currentFix(), FixKind::None); // the fix sequence restarts
            rx->advance(20);
            QVERIFY(rx->currentFix() != FixKind::None);
            const auto q = query(*rx);
            QCOMPARE(q.status->gpsAlmanac, t != "CSTART"); // a cold start drops the almanacs
            QCOMPARE(q.status->clockRestoredHotStart, t == "HSTART");
            return;
        }
        const auto q = query(*rx);
        QVERIFY(q.nquery && q.config1 && q.config2);
        Sentence nq;
        QVERIFY(nq.parse(*q.nquery));
        if (key.rfind("output.", 0) == 0 && key != "output.NMEAV" && key != "output.RATE") {
            const std::string msg = key.substr(7);
            int idx = -1;
            for (std::size_t i = 0; i < geostar::Nquery::kNames.size(); ++i)
                if (geostar::Nquery::kNames[i] == msg) idx = static_cast<int>(i);
            QVERIFY(idx >= 0);
            const std::string code(nq.field(4 + idx));
            QCOMPARE(code != "0", value == "1");
            rx->takeOutput();
            rx->advance(3);
            const auto s = summarize(rx->takeOutput(), "geostar");
            if (msg != "RLM") QCOMPARE(s.count(msg) > 0, value == "1");
        } else if (key == "output.NMEAV") {
            QCOMPARE(std::string(nq.field(3)), value);
        } else if (key == "output.RATE") {
            QCOMPARE(q.config1->rateHz, std::stoi(value));
            QCOMPARE(geostar::rateCodeToHz(std::stoi(std::string(nq.field(2)))), std::stoi(value));
            rx->takeOutput();
            rx->advance(2.0);
            QCOMPARE(summarize(rx->takeOutput(), "geostar").count("GGA"), 2 * std::stoi(value));
        } else if (key == "power.PSM") {
            QCOMPARE(q.config1->powerSavingEnabled, value == "1");
        } else if (key == "nav.ELEV") {
            QCOMPARE(st.integer("nav.ELEV"), std::stoll(value));
            rx->advance(1.0);
            for (const SimSatellite &s : rx->lastSnapshot().satellites)
                if (s.used) QVERIFY(s.elevation >= std::stoi(value));
        } else if (key == "nav.DAT") {
            QCOMPARE(q.config2->datumName(),
                     std::string_view(value == "P90" ? "PZ-90.11" : "WGS-84"));
            rx->takeOutput();
            rx->advance(1.0);
            const auto dtm = summarize(rx->takeOutput(), "geostar").all("DTM");
            QVERIFY(!dtm.empty());
            QVERIFY(dtm.back().rfind("$GPDTM," + value + ",", 0) == 0);
        } else if (key == "nav.NVS") {
            QCOMPARE(q.config1->gps, value != "GLN");
            QCOMPARE(q.config1->glonass, value != "GPS");
            QCOMPARE(q.config1->galileo, value == "MIX");
            rx->takeOutput();
            rx->advance(1.0);
            const auto s = summarize(rx->takeOutput(), "geostar");
            QCOMPARE(s.byAddress.count("GLGSA") > 0, value != "GPS");
            QCOMPARE(s.byAddress.count("GPGSA") > 0, value != "GLN");
        } else if (key == "port.STOP") {
            QCOMPARE(st.integer("port.STOP"), std::stoll(value));
        } else if (t == "SAVEFL") {
            QVERIFY(q.status->flashWriteInProgress);
            rx->advance(1.5);
            QVERIFY(!query(*rx).status->flashWriteInProgress);
        } else if (key != "port.BDR") {
            QFAIL("command not checked");
        }
    }
    // A set command as the settings engine sends it, then the engine's read-back: the store
    // holds the command's value, and the reply reports it as the dialect reads it (what the
    // settings engine and fuzz_settings_roundtrip rely on).
    void everySetCommandIsStoredAndReadBack_data() {
        QTest::addColumn<QString>("text");
        for (const geostar::CommandDef &c : geostar::commands())
            if (!c.settingKey.empty() && !c.settingKey.starts_with("action."))
                QTest::newRow(std::string(c.text).c_str())
                        << QString::fromUtf8(c.text.data(), c.text.size());
    }
    void everySetCommandIsStoredAndReadBack() {
        QFETCH(QString, text);
        const geostar::CommandDef *def = geostar::findCommand(text.toStdString());
        QVERIFY(def);
        const std::string key(def->settingKey), value(def->value);
        auto rx = makeGeoStar();
        rx->advance(1.5);
        const KeyValue change{key, value};
        const EncodeResult write = encodeSettings(rx->dialect(), std::span(&change, 1));
        QVERIFY2(write.ok(), write.error.c_str());
        for (const std::string &s : write.sentences) rx->receive(s + "\r\n");
        rx->advance(0.5);
        QCOMPARE(rx->settings().value(key), value);
        const std::vector<std::string> keys{key};
        const EncodeResult read = encodeQueries(rx->dialect(), keys);
        if (!read.ok()) return; // write-only (elevation mask, port): the store is all there is
        rx->takeOutput();
        for (const std::string &s : read.sentences) rx->receive(s + "\r\n");
        rx->advance(0.5);
        std::vector<KeyValue> reported;
        static const DialectRegistry registry = makeBuiltinRegistry();
        DecoderOptions o;
        o.dialect = "geostar";
        StreamDecoder d(registry, o);
        d.feed(rx->takeOutput(), [&](const SentenceEvent &ev) {
            if (ev.message) geostar::extractSettings(*ev.message, reported);
        });
        int found = 0;
        for (const KeyValue &kv : reported)
            if (kv.key == key) {
                QCOMPARE(kv.value, value);
                ++found;
            }
        QVERIFY(found > 0);
    }
    void savedSettingsSurviveAPowerCycleOthersDoNot() {
        auto rx = makeGeoStar();
        rx->advance(2);
        for (auto t : {"RATE05", "NMEAV4", "GSVOFF", "RMC ON", "DATP90", "ELEV12"}) command(*rx, t);
        rx->powerCycle(); // not saved: back to the defaults
        rx->advance(0.5);
        QCOMPARE(rx->settings().integer("output.RATE"), 1LL);
        QCOMPARE(rx->settings().integer("output.NMEAV"), 2LL);
        auto q = query(*rx);
        QVERIFY(!q.status->settingsLoadedFromFlash);
        QCOMPARE(QString::fromStdString(*q.nquery),
                 QStringLiteral("$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71"));
        for (auto t : {"RATE05", "NMEAV4", "GSVOFF", "RMC ON", "DATP90", "ELEV12"}) command(*rx, t);
        rx->advance(35); // almanacs complete
        command(*rx, "SAVEFL");
        command(*rx, "RATE10"); // after the save: lost at power-off
        rx->advance(2);
        rx->powerCycle();
        rx->advance(0.5);
        QCOMPARE(rx->settings().integer("output.RATE"), 5LL);
        QCOMPARE(rx->settings().integer("output.NMEAV"), 4LL);
        QCOMPARE(rx->settings().value("nav.DAT"), std::string("P90"));
        QCOMPARE(rx->settings().integer("nav.ELEV"), 12LL);
        q = query(*rx);
        QVERIFY(q.status->settingsLoadedFromFlash);
        QVERIFY(q.status->gpsAlmanac); // almanacs from flash at once
        Sentence nq;
        QVERIFY(nq.parse(*q.nquery));
        QCOMPARE(std::string(nq.field(2)), std::string("1")); // 5 Hz
        QCOMPARE(std::string(nq.field(3)), std::string("4"));
        QCOMPARE(std::string(nq.field(4 + 3)), std::string("0")); // GSV off
        QCOMPARE(std::string(nq.field(4 + 4)), std::string("R")); // RMC on
    }
    void nmeaVersionSwitchesTheNumbering() {
        auto rx = makeGeoStar(7);
        rx->advance(10.5);
        rx->takeOutput();
        rx->advance(1.0);
        auto s = summarize(rx->takeOutput(), "geostar");
        QCOMPARE(s.checksumErrors + s.decodeErrors, 0);
        // v2.x: GSV only under GP, three-digit ids, Galileo 101-136; GSA per system.
        QVERIFY(!s.byAddress.count("GLGSV") && !s.byAddress.count("GAGSV"));
        bool galileo = false;
        for (const std::string &l : s.all("GSV")) {
            Sentence g;
            QVERIFY(g.parse(l));
            for (std::size_t i = 3; i + 3 < g.fieldCount() + 1; i += 4) {
                if (g.field(i).empty()) continue;
                QCOMPARE(g.field(i).size(), std::size_t(3));
                const int id = std::stoi(std::string(g.field(i)));
                galileo = galileo || (id >= 101 && id <= 136);
            }
        }
        QVERIFY(galileo);
        QVERIFY(s.byAddress.count("GPGSA") && s.byAddress.count("GLGSA") &&
                s.byAddress.count("GAGSA"));
        command(*rx, "NMEAV4");
        command(*rx, "GLL ON");
        rx->advance(1.0);
        rx->takeOutput();
        rx->advance(1.0);
        s = summarize(rx->takeOutput(), "geostar");
        QCOMPARE(s.checksumErrors + s.decodeErrors, 0);
        QVERIFY(s.byAddress.count("GPGSV") && s.byAddress.count("GLGSV") &&
                s.byAddress.count("GAGSV"));
        for (const std::string &l : s.all("GAGSV")) {
            Sentence g;
            QVERIFY(g.parse(l));
            QCOMPARE(std::string(g.field(g.fieldCount() - 1)), std::string("7")); // E1B/C
            QVERIFY(std::stoi(std::string(g.field(3))) <= 36);
        }
        const auto gsa = s.all("GSA");
        QCOMPARE(gsa.size(), std::size_t(3));
        for (std::size_t i = 0; i < gsa.size(); ++i) {
            Sentence g;
            QVERIFY(g.parse(gsa[i]));
            QCOMPARE(std::string(g.address()), std::string("GNGSA"));
            QCOMPARE(std::string(g.field(g.fieldCount() - 1)), std::to_string(i + 1));
        }
        QVERIFY(s.byAddress.count("GNGNS") && s.byAddress.count("GPGNS"));
        QVERIFY(s.byAddress.count("GNGLL") && s.byAddress.count("GPGGA")); // GGA: GP only
    }
    void allOutputOffSendsTheQueriesEverySecond() {
        auto rx = makeGeoStar();
        rx->advance(1.5);
        for (auto t : {"GGAOFF", "GSAOFF", "GSVOFF", "ZDAOFF", "DTMOFF"}) command(*rx, t);
        rx->takeOutput();
        rx->advance(3.0);
        const auto r = replies(rx->takeOutput());
        QCOMPARE(r.rqueries, 3);
        QCOMPARE(r.nqueries, 3);
    }
    void baudChangeTakesEffectAtOnce() {
        auto rx = makeGeoStar();
        rx->setLineBaud(115200);
        rx->advance(1.5);
        command(*rx, "BDR009");
        QCOMPARE(rx->baud(), 9600);
        rx->takeOutput();
        rx->advance(2.0);
        QCOMPARE(summarize(rx->takeOutput()).lines.size(), std::size_t(0)); // garbage
        command(*rx, "RQUERY"); // ignored: the UART reads garbage at the wrong speed
        rx->setLineBaud(9600);
        rx->advance(2.0);
        const std::string out = rx->takeOutput();
        QVERIFY(summarize(out, "geostar").count("GGA") > 0);
        QCOMPARE(replies(out).rqueries, 0);
    }
};

QTEST_APPLESS_MAIN(TstSimGeoStarReceiver)
#include "tst_sim_geostar_receiver.moc"
