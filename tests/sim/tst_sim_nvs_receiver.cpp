// The simulated NV08C-RTK(-A), in simulated time: default output, RTK sequence, every command's
// reply (judged by the NVS dialect's own reply rules) and effect, flash persistence, baud change.
#include "builtin/simulators.h"
#include "nvs/sim/nvs_sim_receiver.h"
#include "sim/rtcm_base_station.h"
#include "sim_output.h"

#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nvs/nvs_dialect.h"
#include "nvs/nvs_encoders.h"

#include <QTest>

#include <set>

using namespace gnss;
using namespace gnss::sim;
using gnss::test::summarize;

namespace {

std::unique_ptr<Receiver> makeNvs(std::uint32_t seed = 1, bool internalBase = true) {
    SimOptions o;
    o.seed = seed;
    o.internalBase = internalBase;
    return makeReceiver("nvs", o);
}

void command(Receiver &rx, const std::string &body) {
    rx.receive(buildSentence(body) + "\r\n");
}

// The dialect's reply rule verdict for what came back after `body` (sentences of other
// addresses are skipped, as the command queue skips them).
ReplyVerdict verdict(const std::string &body, const std::string &output) {
    const std::string cmdLine = buildSentence(body);
    Sentence cmd;
    cmd.parse(cmdLine);
    const ReplyRule *rule = nullptr;
    for (const ReplyRule &r : nvs::dialect().replyRules) {
        if (r.commandAddress != cmd.address()) continue;
        if (!r.firstField.empty() && r.firstField != cmd.field(0)) continue;
        rule = &r;
        break;
    }
    if (!rule || !rule->classify) return ReplyVerdict::NotMine;
    ReplyProgress progress;
    ReplyVerdict v = ReplyVerdict::NotMine;
    for (const auto &l : summarize(output, "nvs").lines) {
        Sentence reply;
        if (!reply.parse(l.line)) continue;
        v = rule->classify(cmd, reply, progress);
        if (v == ReplyVerdict::Accepted || v == ReplyVerdict::Refused) return v;
    }
    return v;
}

// The verdict on what `rx` answers to `body`, sent `after` seconds on (what it said before that
// is dropped).
ReplyVerdict answer(Receiver &rx, double after, const std::string &body) {
    rx.advance(after);
    rx.takeOutput();
    command(rx, body);
    return verdict(body, rx.takeOutput());
}

// The dialect's encoder of a proprietary sentence the receiver sends, applied to its decoding
// (PNVGTMC at the default position decimals, 4.2); nullopt when the address has none.
std::optional<std::string> reencoded(const std::string &line) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    DecoderOptions o;
    o.dialect = "nvs";
    StreamDecoder dec(registry, o);
    std::optional<std::string> out;
    dec.decodeLine(line, [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        const Message &m = *ev.message;
        EncodeResult r;
        if (const auto *x = message_cast<nvs::Ver>(m))
            r = nvs::encodeVer(*x);
        else if (const auto *x = message_cast<nvs::Bss>(m))
            r = nvs::encodeBss(*x);
        else if (const auto *x = message_cast<nvs::Tst>(m))
            r = nvs::encodeTst(*x);
        else if (const auto *x = message_cast<nvs::Imu>(m))
            r = nvs::encodeImu(*x);
        else if (const auto *x = message_cast<nvs::Brs>(m))
            r = nvs::encodeBrs(*x);
        else if (const auto *x = message_cast<nvs::Bls>(m))
            r = nvs::encodeBls(*x);
        else if (const auto *x = message_cast<nvs::Vog>(m))
            r = nvs::encodeVog(*x);
        else if (const auto *x = message_cast<nvs::Idl>(m))
            r = nvs::encodeIdl(*x);
        else if (const auto *x = message_cast<nvs::Tme>(m))
            r = nvs::encodeTme(*x);
        else if (const auto *x = message_cast<nvs::Tmu>(m))
            r = nvs::encodeTmu(*x);
        else if (const auto *x = message_cast<nvs::Tmc>(m))
            r = nvs::encodeTmc(*x, 7);
        else if (const auto *x = message_cast<nvs::Sdp>(m))
            r = nvs::encodeSdp(*x);
        else if (const auto *x = message_cast<nvs::Sdv>(m))
            r = nvs::encodeSdv(*x);
        else if (const auto *x = message_cast<nvs::Sdh>(m))
            r = nvs::encodeSdh(*x);
        else if (const auto *x = message_cast<nvs::Dop>(m))
            r = nvs::encodeDop(*x);
        else
            return;
        out = r.ok() ? r.sentences.front() : "refused: " + r.error;
    });
    return out;
}

int ggaQualityOfLast(const std::string &out) {
    const auto gga = summarize(out, "nvs").all("GGA");
    if (gga.empty()) return -1;
    Sentence s;
    s.parse(gga.back());
    return std::atoi(std::string(s.field(5)).c_str());
}

} // namespace

class TstSimNvsReceiver : public QObject {
    Q_OBJECT
private slots:
    void defaultOutputIsFiveHertzAt115200() {
        auto rx = makeNvs();
        QCOMPARE(rx->baud(), 115200);
        QCOMPARE(rx->epochInterval(), 0.2);
        rx->advance(1.99); // epochs 0.0 .. 1.8
        const auto s = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        QCOMPARE(s.byType.at("GGA"), 10);
        QCOMPARE(s.byType.at("RMC"), 10);
        QCOMPARE(s.byType.at("VTG"), 10);
        QCOMPARE(s.byType.at("ZDA"), 2);     // every 5th epoch
        QCOMPARE(s.byType.at("PNVGBSS"), 2); // every 5th epoch
        QCOMPARE(s.byType.at("PNVGTST"), 1); // once at start (4.7)
        QVERIFY(s.byAddress.count("GPGSV") && s.byAddress.count("GLGSV"));
        QVERIFY(!s.byAddress.count("GAGSV")); // a GPS/GLONASS receiver
    }
    void rtkGoesAutonomousThenFloatThenFixed() {
        auto rx = makeNvs();
        command(*rx, "PNVGRZB,SDP,5,BRS,5,GGA,5,BSS,5");
        std::vector<int> qualities;
        std::vector<double> sigmas;
        for (int i = 0; i < 25; ++i) {
            rx->advance(1.0);
            const auto s = summarize(rx->takeOutput(), "nvs");
            for (const auto &l : s.lines) {
                Sentence x;
                x.parse(l.line);
                if (l.address == "PNVGSDP" && !x.field(1).empty())
                    sigmas.push_back(std::atof(std::string(x.field(1)).c_str()));
            }
            qualities.push_back(ggaQualityOfLast(s.lines.empty() ? "" : [&] {
                std::string all;
                for (const auto &l : s.lines) all += l.line + "\r\n";
                return all;
            }()));
        }
        QCOMPARE(qualities.front(), 0);
        QVERIFY(std::find(qualities.begin(), qualities.end(), 1) != qualities.end());
        QVERIFY(std::find(qualities.begin(), qualities.end(), 5) != qualities.end());
        QCOMPARE(qualities.back(), 4);
        QVERIFY(rx->currentFix() == FixKind::Fixed);
        // Standard deviations consistent with the fix type: metres, then centimetres, then mm.
        QVERIFY(sigmas.front() > 0.2);
        QVERIFY(sigmas.back() < 0.02);
        // Base statistics and baseline: messages counted, the base 4.8 km away.
        command(*rx, "GPGPQ,PNVGBSS");
        const auto bss = summarize(rx->takeOutput(), "nvs").all("PNVGBSS");
        QCOMPARE(bss.size(), std::size_t(1));
        Sentence b;
        b.parse(bss.front());
        QVERIFY(std::atoi(std::string(b.field(0)).c_str()) > 30);
        QVERIFY(std::abs(std::atof(std::string(b.field(3)).c_str()) - 4769.2) < 1);
        QVERIFY(!b.field(4).empty());
    }
    // Without the simulator's own base, a rover stays autonomous until RTCM 3 comes from the
    // host; with corrections it reaches float, then fixed; when they stop it falls back.
    void rtkNeedsCorrectionsFromTheHost() {
        auto rx = makeNvs(1, false);
        command(*rx, "PNVGRTK,RTCMAGE,10");
        rx->advance(30);
        QVERIFY(rx->currentFix() == FixKind::Autonomous); // no corrections: never RTK
        rx->takeOutput();
        RtcmBaseStation base;
        std::vector<FixKind> seen;
        for (int i = 0; i < 25; ++i) {
            base.advance(1.0);
            const std::string burst = base.takeOutput();
            // Cut anywhere: frames are found all the same.
            rx->receive(burst.substr(0, burst.size() / 2));
            rx->receive(burst.substr(burst.size() / 2));
            rx->advance(1.0);
            seen.push_back(rx->currentFix());
        }
        QVERIFY(seen.front() == FixKind::Autonomous);
        QVERIFY(std::find(seen.begin(), seen.end(), FixKind::Float) != seen.end());
        QVERIFY(seen.back() == FixKind::Fixed);
        // PNVGBSS counts the frames received and the bad ones.
        rx->takeOutput();
        command(*rx, "GPGPQ,PNVGBSS");
        const auto bss = summarize(rx->takeOutput(), "nvs").all("PNVGBSS");
        QCOMPARE(bss.size(), std::size_t(1));
        Sentence b;
        b.parse(bss.front());
        QVERIFY(std::atoi(std::string(b.field(0)).c_str()) >= 50);
        QCOMPARE(std::string(b.field(1)), std::string("0"));
        // A corrupted frame is counted as bad.
        base.advance(1.0);
        std::string bad = base.takeOutput();
        bad[5] = char(bad[5] ^ 0x10); // inside the first frame's payload
        rx->receive(bad);
        command(*rx, "GPGPQ,PNVGBSS");
        const auto after = summarize(rx->takeOutput(), "nvs").all("PNVGBSS");
        QCOMPARE(after.size(), std::size_t(1));
        b.parse(after.front()); // (the sentence refers to the text: keep it alive)
        QVERIFY(std::atoi(std::string(b.field(1)).c_str()) >= 1);
        // Corrections stop: autonomous again once they are older than RTCMAGE (10 s here).
        rx->advance(12);
        QVERIFY(rx->currentFix() == FixKind::Autonomous);
    }
    void pvtRateChangesTheOutputRate() {
        auto rx = makeNvs();
        QCOMPARE(int(answer(*rx, 0.5, "PNVGRTK,PVTRATE,1")), int(ReplyVerdict::Accepted));
        rx->advance(10.0);
        QCOMPARE(summarize(rx->takeOutput(), "nvs").byType.at("GGA"), 10);
        QCOMPARE(static_cast<NvsReceiver &>(*rx).settings().value("rtk.PVTRATE"), std::string("1"));
    }
    void outOfRangeValuesAreNotTakenAndTheReplySaysSo_data() {
        QTest::addColumn<QString>("body");
        QTest::newRow("PVTRATE 3") << "PNVGRTK,PVTRATE,3";
        QTest::newRow("ELGPS 91") << "PNVGRTK,ELGPS,91";
        QTest::newRow("BASEID 4096") << "PNVGRTK,BASEID,4096";
        QTest::newRow("RZA baud 1234") << "PNVGRZA,0,1234,1";
        QTest::newRow("RZA protocol 5") << "PNVGRZA,1,9600,5";
        QTest::newRow("NME time decimals 7") << "PNVGNME,7,5";
        QTest::newRow("PPS duration 0") << "PNVGPPS,,,,,0,,";
        QTest::newRow("IDL mode 2") << "PNVGIDL,MODE,2";
    }
    void outOfRangeValuesAreNotTakenAndTheReplySaysSo() {
        QFETCH(QString, body);
        auto rx = makeNvs();
        QCOMPARE(int(answer(*rx, 0.1, body.toStdString())), int(ReplyVerdict::Refused));
        QCOMPARE(rx->baud(), 115200);
        QCOMPARE(rx->epochInterval(), 0.2);
    }
    void everyCommandIsAnsweredAsItsReplyRuleExpects_data() {
        QTest::addColumn<QString>("body");
        for (const char *b :
             {"PNVGVER", "GPGPQ,PNVGTST", "GPGPQ,GGA", "PNVGNME,3,5,1", "PNVGPPS,A,I,N,0,500,E,20",
              "PNVGPPS,,,,,,,", "PNVGRTK,MODE,SNR,ELGPS,BASEXYZ,INITGPSWEEK",
              "PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737",
              "PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040", "PNVGRTK,SFTRS,0.1",
              "PNVGCFG,W", "PNVGCFG,E", "PNVGIDL,MODE,1", "PNVGIDL,ADD,0003,0.0720", "PNVGIDL,ADD",
              "PNVGIDL,SHOW", "PNVGIDL,CLEAR", "PNVGRZA,2,9600,7"})
            QTest::newRow(b) << b;
    }
    void everyCommandIsAnsweredAsItsReplyRuleExpects() {
        QFETCH(QString, body);
        auto rx = makeNvs();
        QCOMPARE(int(answer(*rx, 4.1, body.toStdString())), int(ReplyVerdict::Accepted));
    }
    void stationListAddShowRemove() {
        auto rx = makeNvs();
        command(*rx, "PNVGIDL,ADD,0001,0.0");
        command(*rx, "PNVGIDL,ADD,0043,0.072");
        rx->takeOutput();
        command(*rx, "PNVGIDL,SHOW");
        const auto items = summarize(rx->takeOutput(), "nvs").all("PNVGIDL");
        QCOMPARE(items.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(items[1]),
                 QString::fromStdString(buildSentence("PNVGIDL,2,2,0043,0.0720")));
        command(*rx, "PNVGIDL,REMOVE,0043");
        QCOMPARE(int(verdict("PNVGIDL,REMOVE,0043", rx->takeOutput())),
                 int(ReplyVerdict::Accepted));
        command(*rx, "PNVGIDL,REMOVE,0043");
        QCOMPARE(int(verdict("PNVGIDL,REMOVE,0043", rx->takeOutput())), int(ReplyVerdict::Refused));
    }
    void rzbReplacesTheOutputList() {
        auto rx = makeNvs();
        command(*rx, "PNVGRZB");
        rx->advance(2);
        // Nothing but the test results the receiver sends once it starts (4.7).
        const auto cleared = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(cleared.lines.size(), std::size_t(1));
        QCOMPARE(cleared.lines.front().address, std::string("PNVGTST"));
        command(*rx, "PNVGRZB,RMC,1,GSV,5,PNVGDOP,1,VOG,1");
        rx->advance(2.0);
        const auto s = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(s.byType.at("RMC"), 10);
        QCOMPARE(s.byType.at("PNVGDOP"), 10);
        QCOMPARE(s.byType.at("PNVGVOG"), 10);
        QVERIFY(s.byType.at("GSV") >= 2);
        QVERIFY(!s.byType.count("GGA"));
    }
    void headingModeGivesHdtAndBaseline() {
        auto rx = makeNvs();
        command(*rx, "PNVGRTK,MODE,4,BASELINE,1.5");
        command(*rx, "PNVGRZB,HDT,5,BLS,5,SDH,5,IMU,5");
        rx->advance(25);
        rx->takeOutput();
        rx->advance(1);
        const auto s = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(s.decodeErrors, 0);
        const auto hdts = s.all("HDT"), blss = s.all("PNVGBLS");
        Sentence hdt, bls;
        hdt.parse(hdts.back());
        bls.parse(blss.back());
        QVERIFY(std::abs(std::atof(std::string(hdt.field(0)).c_str()) - 40.6) < 1.0);
        QVERIFY(std::abs(std::atof(std::string(bls.field(4)).c_str()) - 1.5) < 1e-3);
        QCOMPARE(bls.field(7), std::string_view("R"));
        QVERIFY(!s.all("PNVGIMU").empty());
    }
    void timeMarkEventsCarryTowUtcAndFix() {
        auto rx = makeNvs();
        command(*rx, "PNVGRZB,TME,1,TMU,1,TMC,1");
        rx->advance(10);
        const auto s = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(s.decodeErrors, 0);
        QVERIFY(s.byType.at("PNVGTME") >= 8);
        QCOMPARE(s.byType.at("PNVGTME"), s.byType.at("PNVGTMU"));
        QCOMPARE(s.byType.at("PNVGTME"), s.byType.at("PNVGTMC"));
    }
    void savedSettingsSurviveAPowerCycleOthersDoNot() {
        auto rx = makeNvs();
        command(*rx, "PNVGRTK,PVTRATE,10");
        command(*rx, "PNVGCFG,W");
        command(*rx, "PNVGRTK,PVTRATE,2");
        command(*rx, "PNVGRZB"); // an empty output list, not saved
        QCOMPARE(rx->epochInterval(), 0.5);
        rx->powerCycle();
        QCOMPARE(rx->epochInterval(), 0.1);
        rx->takeOutput();
        rx->advance(1.0);
        const auto after = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(after.byType.at("GGA"), 10); // the saved list at the saved 10 Hz is back
        // Erase: defaults come back at the next power cycle (or at once with R).
        command(*rx, "PNVGCFG,R");
        QCOMPARE(rx->epochInterval(), 0.2);
    }
    void resetRestartsTheFixSequenceButKeepsSettings() {
        auto rx = makeNvs();
        command(*rx, "PNVGRTK,PVTRATE,1");
        rx->advance(20);
        QVERIFY(rx->currentFix() == FixKind::Fixed);
        command(*rx, "PNVGRST,F");
        rx->takeOutput();
        rx->advance(2);
        QCOMPARE(ggaQualityOfLast(rx->takeOutput()), 0);
        QCOMPARE(rx->epochInterval(), 1.0); // user settings kept (4.3)
        rx->advance(40);
        QVERIFY(rx->currentFix() == FixKind::Fixed);
    }
    void rzaAnswersAtTheOldSpeedThenSwitches() {
        auto rx = makeNvs();
        rx->setLineBaud(115200);
        QCOMPARE(int(answer(*rx, 0.3, "PNVGRZA,0,9600,1")), int(ReplyVerdict::Accepted));
        QCOMPARE(rx->baud(), 9600);
        rx->advance(1);
        const std::string garbage = rx->takeOutput();
        QVERIFY(!garbage.empty() && garbage.find('$') == std::string::npos);
        rx->setLineBaud(9600);
        rx->advance(1);
        QVERIFY(summarize(rx->takeOutput(), "nvs").byType.count("GGA"));
    }
    void slowAndMissingRepliesFollowTheFaults() {
        std::string error;
        SimOptions o;
        o.faults = *parseFaults("slowreply=800,noreply=PNVGVER", error);
        auto rx = makeReceiver("nvs", o);
        command(*rx, "PNVGRTK,PVTRATE");
        command(*rx, "PNVGVER");
        QVERIFY(summarize(rx->takeOutput(), "nvs").all("PNVGRTK").empty());
        rx->advance(0.9);
        const auto s = summarize(rx->takeOutput(), "nvs");
        QCOMPARE(s.all("PNVGRTK").size(), std::size_t(1));
        QVERIFY(s.all("PNVGVER").empty());
    }
    // What it sends of its own comes from the dialect's encoders: each proprietary sentence,
    // decoded and encoded again, is the same bytes.
    void everyProprietarySentenceIsItsEncodersOwn() {
        auto rx = makeNvs(3);
        command(*rx, "PNVGRZB,BSS,1,TST,5,IMU,1,BRS,1,BLS,1,VOG,1,SDP,1,SDV,1,SDH,1,DOP,1,TME,1,"
                     "TMU,1,TMC,1");
        command(*rx, "PNVGIDL,ADD,0043,0.072");
        command(*rx, "PNVGIDL,SHOW");
        command(*rx, "PNVGVER");
        rx->advance(3); // not yet fixed: the fields of a solution not valid
        command(*rx, "PNVGRTK,MODE,4");
        rx->advance(25); // RTK fixed with heading
        command(*rx, "PNVGIDL,REMOVE,0043");
        command(*rx, "PNVGIDL,REMOVE,0043");
        command(*rx, "PNVGIDL,SHOW");
        rx->advance(1);
        std::set<std::string> seen;
        for (const auto &l : summarize(rx->takeOutput(), "nvs").lines) {
            const auto again = reencoded(l.line);
            if (!again) continue;
            seen.insert(l.address);
            QCOMPARE(QString::fromStdString(*again), QString::fromStdString(l.line));
        }
        QCOMPARE(int(seen.size()), 15); // every output sentence of the receiver
    }
    // Its settings are the schema's keys: commands land there, PNVGCFG,W copies them to flash.
    void commandsLandInTheSettingsUnderTheSchemasKeys() {
        auto rx = makeNvs();
        const auto &settings = static_cast<NvsReceiver &>(*rx).settings();
        for (const SettingDef &def : nvs::dialect().settings)
            if (!def.defaultValue.empty())
                QCOMPARE(settings.value(def.key), std::string(def.defaultValue));
        QVERIFY(!settings.value("rtk.BASEXYZ").empty()); // the simulated base's position
        QCOMPARE(settings.value("output.COM1"),
                 std::string("GGA:1;GSA:1;GSV:5;RMC:1;VTG:1;ZDA:5;PNVGBSS:5"));
        command(*rx, "PNVGNME,3,5,1");
        command(*rx, "PNVGPPS,,,G,,,,");
        command(*rx, "PNVGRZB,PORT,2,RMC,1,BSS,5");
        command(*rx, "PNVGRZA,3,9600,7");
        command(*rx, "PNVGIDL,ADD,0043,0.072");
        QCOMPARE(settings.value("nmea.position_decimals"), std::string("5"));
        QCOMPARE(settings.value("pps.reference"), std::string("G"));
        QCOMPARE(settings.value("output.COM2"), std::string("RMC:1;PNVGBSS:5"));
        QCOMPARE(settings.value("port.USB.baud"), std::string("9600"));
        QCOMPARE(settings.value("port.USB.protocol"), std::string("7"));
        QCOMPARE(settings.value("idl.stations"), std::string("43:0.0720"));
        QCOMPARE(settings.saved().at("pps.reference"), std::string("U"));
        command(*rx, "PNVGCFG,W");
        QCOMPARE(settings.saved().at("pps.reference"), std::string("G"));
        QCOMPARE(settings.saved().at("idl.stations"), std::string("43:0.0720"));
    }
    void sameSeedSameOutput() {
        auto a = makeNvs(5), b = makeNvs(5);
        for (auto *rx : {a.get(), b.get()}) {
            command(*rx, "PNVGRZB,GGA,1,PNVGSDP,1,PNVGIMU,1,TMC,1");
            rx->advance(20);
        }
        QCOMPARE(a->takeOutput(), b->takeOutput());
    }
};

QTEST_APPLESS_MAIN(TstSimNvsReceiver)
#include "tst_sim_nvs_receiver.moc"
