// The simulated VT002, in simulated time: default output (2.1.8), every PNMRX command's reply or
// effect, PNMRX603 read back through the nemerix dialect, PNMRX300-304 decoded and consistent
// with the sky model's orbits.
#include "builtin/simulators.h"
#include "nemerix/sim/nemerix_sim_receiver.h"
#include "sim_output.h"
#include "sim_receiver.h"

#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_dialect.h"
#include "nemerix/nemerix_ephemeris.h"
#include "nemerix/nemerix_messages.h"

#include <QTest>

#include <cmath>

using namespace gnss;
using namespace gnss::sim;
using gnss::test::summarize;

namespace {

std::unique_ptr<NemerixReceiver> makeNemerix(std::uint32_t seed = 1) {
    return gnss::test::makeReceiverAs<NemerixReceiver>("nemerix", seed);
}

void command(Receiver &rx, const std::string &body) {
    rx.receive(buildSentence(body) + "\r\n");
}

// Settings read back from PNMRX603 by the dialect's own extractSettings.
std::map<std::string, std::string> readBack(Receiver &rx) {
    rx.takeOutput();
    command(rx, "PNMRX603");
    rx.advance(0.01);
    static const DialectRegistry registry = makeBuiltinRegistry();
    DecoderOptions o;
    o.dialect = "nemerix";
    StreamDecoder d(registry, o);
    std::vector<KeyValue> kv;
    int reports = 0;
    d.feed(rx.takeOutput(), [&](const SentenceEvent &ev) {
        if (!ev.message || !message_cast<nemerix::SettingsReport>(*ev.message)) return;
        ++reports;
        nemerix::dialect().extractSettings(*ev.message, kv);
    });
    std::map<std::string, std::string> out;
    for (const KeyValue &k : kv) out[k.key] = k.value;
    out["#reports"] = std::to_string(reports);
    return out;
}

} // namespace

class TstSimNemerixReceiver : public QObject {
    Q_OBJECT
private slots:
    void defaultOutputIsGgaRmcVtgEverySecondGsaGsvEveryThree() {
        auto rx = makeNemerix();
        QCOMPARE(rx->baud(), 9600);
        rx->advance(8.5); // epochs 0..8
        const auto s = summarize(rx->takeOutput(), "nemerix");
        QCOMPARE(s.checksumErrors, 0); // the checksum is optional on input, always sent here
        QCOMPARE(s.decodeErrors, 0);
        QCOMPARE(s.count("GGA"), 9);
        QCOMPARE(s.count("RMC"), 9);
        QCOMPARE(s.count("VTG"), 9);
        QCOMPARE(s.count("GSA"), 3); // seconds 0, 3, 6
        QVERIFY(!s.count("GLL") && !s.count("ZDA"));
        for (const auto &l : s.lines) {
            QVERIFY2(l.address.rfind("GP", 0) == 0, l.line.c_str()); // GPS only
            QVERIFY(l.line.find("*") != std::string::npos);
        }
        // NMEA 3.0, at most 12 satellites in GSV: 1..3 sentences, no signal id.
        for (const std::string &g : s.all("GSV")) {
            Sentence v;
            QVERIFY(v.parse(g));
            QVERIFY(std::stoi(std::string(v.field(0))) <= 3);
            QVERIFY(std::stoi(std::string(v.field(2))) <= 12);
            QVERIFY(v.fieldCount() <= 19);
        }
        QCOMPARE(rx->droppedSentences(), std::int64_t(0));
    }
    void ratesAndSequenceCommandsChangeTheOutput() {
        auto rx = makeNemerix();
        rx->advance(0.5);
        command(*rx, "PNMRX103,GSV,2,GGA,1,ZDA,1,GSA,0");
        rx->takeOutput();
        rx->advance(6.0);
        auto s = summarize(rx->takeOutput(), "nemerix");
        QCOMPARE(s.count("ZDA"), 6);
        QCOMPARE(s.count("GSA"), 0);
        QVERIFY(s.count("GSV") >= 3);
        auto rb = readBack(*rx);
        QCOMPARE(rb["rate.ZDA"], std::string("1"));
        QCOMPARE(rb["rate.GSV"], std::string("2"));
        command(*rx, "PNMRX103,ALL,0"); // skips all messages
        rx->takeOutput();
        rx->advance(3.0);
        QCOMPARE(summarize(rx->takeOutput(), "nemerix").lines.size(), std::size_t(0));
        command(*rx, "PNMRX103,ALL,2");
        rx->advance(4.0);
        rx->takeOutput();
        rx->advance(4.0);
        QCOMPARE(summarize(rx->takeOutput(), "nemerix").count("GGA"), 2);
        command(*rx, "PNMRX108,GGA,GLL,GSA"); // only these, every second, in this order
        rx->takeOutput();
        rx->advance(3.0);
        s = summarize(rx->takeOutput(), "nemerix");
        QCOMPARE(s.count("GLL"), 3);
        QVERIFY(!s.count("RMC") && !s.count("GSV"));
        QCOMPARE(s.lines[0].address, std::string("GPGGA"));
        QCOMPARE(s.lines[1].address, std::string("GPGLL"));
        command(*rx, "PNMRX103,GGA,12"); // out of range 0..9: not taken
        QCOMPARE(rx->settings().value("rate.GGA"), std::string("1"));
    }
    void settingsReportReflectsEveryMaskAndDatum() {
        auto rx = makeNemerix();
        rx->advance(1.5);
        command(*rx, "PNMRX110,0,-2:0,1,60,4,35,5,10,6,700");
        command(*rx, "PNMRX106,0,500,-2000,-2000,-2000,8257224,8137000");
        command(*rx, "PNMRX101,,,,,,,14,");
        auto rb = readBack(*rx);
        QCOMPARE(rb["#reports"], std::string("5"));
        QCOMPARE(rb["fix.timeZone"], std::string("-2:0"));
        QCOMPARE(rb["fix.maxPdop"], std::string("6"));
        QCOMPARE(rb["fix.minSnr"], std::string("35"));
        QCOMPARE(rb["fix.minElevation"], std::string("10"));
        QCOMPARE(rb["fix.noiseFloor"], std::string("700"));
        QCOMPARE(rb["datum.mapDatum"], std::string("500"));
        QCOMPARE(rb["datum.dx"], std::string("-2000"));
        QCOMPARE(rb["nav.channels"], std::string("14"));
        // The masks act on the fix and the time zone on ZDA.
        command(*rx, "PNMRX103,ZDA,1");
        rx->advance(2.0);
        for (const SimSatellite &s : rx->lastSnapshot().satellites)
            if (s.used) QVERIFY(s.elevation >= 10 && s.snr >= 35);
        const auto zda = summarize(rx->takeOutput(), "nemerix").all("ZDA");
        QVERIFY(!zda.empty());
        QVERIFY(zda.back().find(",-2,00*") != std::string::npos);
        // Out of range: not taken.
        command(*rx, "PNMRX110,4,50");
        QCOMPARE(rx->settings().value("fix.minSnr"), std::string("35"));
    }
    void versionQueryIsAnswered() {
        auto rx = makeNemerix();
        rx->advance(0.5);
        rx->takeOutput();
        command(*rx, "PNMRX600");
        rx->advance(0.01);
        const auto s = summarize(rx->takeOutput(), "nemerix");
        QCOMPARE(s.all("PNMRX600").size(), std::size_t(1));
        QCOMPARE(s.decodeErrors, 0);
    }
    void resetsRestartTheFixSequence_data() {
        QTest::addColumn<QString>("body");
        QTest::addColumn<bool>("keepsSettings");
        QTest::newRow("no parameter") << "PNMRX111" << true;
        QTest::newRow("HOT") << "PNMRX111,HOT" << true;
        QTest::newRow("WARM") << "PNMRX111,WARM" << true;
        QTest::newRow("COLD") << "PNMRX111,COLD" << true;
        QTest::newRow("FACTORY") << "PNMRX111,FACTORY" << false;
        QTest::newRow("bits reload+cold") << "PNMRX111,3" << false;
        QTest::newRow("101 position") << "PNMRX101,2849000,2183000,5249000," << true;
        QTest::newRow("101 factory") << "PNMRX101,,,,,,,,,8," << false;
    }
    void resetsRestartTheFixSequence() {
        QFETCH(QString, body);
        QFETCH(bool, keepsSettings);
        auto rx = makeNemerix();
        rx->advance(10.5);
        QVERIFY(rx->currentFix() != FixKind::None);
        command(*rx, "PNMRX103,ZDA,1");
        command(*rx, body.toStdString());
        rx->advance(1.0);
        QCOMPARE(rx->currentFix(), FixKind::None);
        // Past the datasheet's time for any start (12, 38, 60 s on average; at most 3 × that).
        rx->advance(181.0);
        QVERIFY(rx->currentFix() != FixKind::None);
        QCOMPARE(rx->settings().value("rate.ZDA") == "1", keepsSettings);
    }
    void stopCoreHoldsTheFixUntilAReset() {
        auto rx = makeNemerix();
        rx->advance(10.5);
        command(*rx, "PNMRX113");
        rx->advance(5.0);
        QCOMPARE(rx->currentFix(), FixKind::None);
        QVERIFY(summarize(rx->takeOutput(), "nemerix").count("GGA") > 0); // still talking
        command(*rx, "PNMRX111");
        rx->advance(40.0); // a hot start: 12 s on average, at most 36
        QVERIFY(rx->currentFix() != FixKind::None);
    }
    void portCommandSwitchesTheSpeedAndIspSilences() {
        auto rx = makeNemerix();
        rx->setLineBaud(9600);
        rx->advance(1.5);
        command(*rx, "PNMRX100,0,4800,0");
        QCOMPARE(rx->baud(), 4800);
        rx->takeOutput();
        rx->advance(2.0);
        QCOMPARE(summarize(rx->takeOutput()).lines.size(), std::size_t(0));
        rx->setLineBaud(4800);
        command(*rx, "PNMRX100,0,4801,0"); // not in the table: refused as a whole
        QCOMPARE(rx->baud(), 4800);
        rx->advance(2.0);
        QVERIFY(summarize(rx->takeOutput(), "nemerix").count("GGA") > 0);
        command(*rx, "PNMRX601");
        rx->takeOutput();
        rx->advance(3.0);
        QCOMPARE(rx->takeOutput().size(), std::size_t(0));
        rx->powerCycle(); // factory settings: 9600 again
        rx->setLineBaud(9600);
        rx->advance(2.0);
        QVERIFY(summarize(rx->takeOutput(), "nemerix").count("GGA") > 0);
    }
    void navigationDataReportsMatchTheSky() {
        auto rx = makeNemerix(5);
        rx->advance(10.5);
        rx->takeOutput();
        command(*rx, "PNMRX107,ALL,1");
        rx->advance(30.0); // reports are spread over the seconds
        static const DialectRegistry registry = makeBuiltinRegistry();
        DecoderOptions o;
        o.dialect = "nemerix";
        StreamDecoder d(registry, o);
        nemerix::EphemerisAssembler assembler;
        int almanacs = 0, ephemerides = 0, iono = 0, utc = 0, health = 0, errors = 0;
        d.feed(rx->takeOutput(), [&](const SentenceEvent &ev) {
            if (!ev.message) {
                ++errors;
                return;
            }
            if (const auto *a = message_cast<nemerix::Almanac>(*ev.message)) {
                ++almanacs;
                // GPS orbits: sqrt(A) about 5153.8 m^1/2, inclination 0.30 + delta-i ~ 55 deg.
                QVERIFY(std::fabs(*a->value(nemerix::Almanac::SqrtA) - 5153.8) < 1.0);
                const double incl = (0.30 + *a->value(nemerix::Almanac::DeltaI)) * 180.0;
                QVERIFY2(std::fabs(incl - 55.0) < 1.0, QByteArray::number(incl));
            } else if (const auto *e = message_cast<nemerix::EphemerisSubframe>(*ev.message)) {
                if (auto eph = assembler.add(*e)) {
                    ++ephemerides;
                    QVERIFY(eph->consistent());
                }
            } else if (message_cast<nemerix::Ionosphere>(*ev.message)) {
                ++iono;
            } else if (message_cast<nemerix::UtcParameters>(*ev.message)) {
                ++utc;
            } else if (message_cast<nemerix::ConstellationHealth>(*ev.message)) {
                ++health;
            }
        });
        QCOMPARE(errors, 0);
        QVERIFY2(almanacs >= 24 && almanacs <= 32, QByteArray::number(almanacs));
        QVERIFY(ephemerides >= 4);
        QCOMPARE(iono, 1);
        QCOMPARE(utc, 1);
        QCOMPARE(health, 1);
        QCOMPARE(rx->droppedSentences(), std::int64_t(0)); // interleaved within 9600 baud
        // "On change": the ephemeris of every satellite once, then again only for new ones.
        command(*rx, "PNMRX107,301,2");
        rx->advance(20.0);
        const int first =
                static_cast<int>(summarize(rx->takeOutput(), "nemerix").all("PNMRX301").size());
        QVERIFY(first >= 12 && first % 3 == 0);
    }
    void almanacUploadIsTaken() {
        auto rx = makeNemerix();
        rx->advance(10.5);
        command(*rx, "PNMRX107,300,1");
        rx->advance(10.0);
        const auto almanac = summarize(rx->takeOutput(), "nemerix").all("PNMRX300");
        QVERIFY(!almanac.empty());
        rx->receive(almanac.front() + "\r\n"); // the upload has the same layout
        QCOMPARE(rx->uploadedAlmanacs(), 1);
    }
};

QTEST_APPLESS_MAIN(TstSimNemerixReceiver)
#include "tst_sim_nemerix_receiver.moc"
