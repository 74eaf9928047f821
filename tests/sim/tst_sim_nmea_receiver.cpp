// The plain NMEA receiver, in simulated time: default sentence set and rate, fix sequence,
// queries, baud mismatch and determinism.
#include "builtin/simulators.h"
#include "sim_output.h"

#include "core/sentence.h"
#include "core/sentence_builder.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;
using gnss::test::summarize;

class TstSimNmeaReceiver : public QObject {
    Q_OBJECT
private slots:
    void defaultOutputIsGgaGsaGsvRmcVtgZdaAtOneHertz() {
        auto rx = makeReceiver("nmea");
        QCOMPARE(rx->baud(), 9600);
        rx->advance(9.95); // epochs at 0..9
        const auto s = summarize(rx->takeOutput(), "nmea");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        QCOMPARE(s.byType.at("GGA"), 10);
        QCOMPARE(s.byType.at("RMC"), 10);
        QCOMPARE(s.byType.at("VTG"), 10);
        QCOMPARE(s.byType.at("ZDA"), 10);
        QVERIFY(s.byType.at("GSA") >= 10);
        QVERIFY(s.byType.at("GSV") >= 40);
        QCOMPARE(s.byType.size(), std::size_t(6));
        // GSV for every constellation the receiver tracks.
        for (auto a : {"GPGSV", "GLGSV", "GAGSV", "GBGSV"}) QVERIFY2(s.byAddress.count(a), a);
    }
    void fixComesAfterTheFirstSecondsAndUsesSeveralSystems() {
        auto rx = makeReceiver("nmea");
        rx->advance(0.5);
        auto s = summarize(rx->takeOutput(), "nmea");
        QVERIFY(s.all("GGA").front().find(",0,00,") != std::string::npos); // no fix yet
        QVERIFY(s.all("RMC").front().find(",V,") != std::string::npos);
        rx->advance(10);
        s = summarize(rx->takeOutput(), "nmea");
        const std::string last = s.all("GGA").back();
        QVERIFY2(last.rfind("$GNGGA", 0) == 0, last.c_str());
        QVERIFY2(last.find(",5545.") != std::string::npos, last.c_str()); // Moscow
        QVERIFY(rx->currentFix() == FixKind::Autonomous);
        QVERIFY(s.all("GSA").size() >= 2); // one per system in use
    }
    void queryIsAnsweredWithTheSentenceAskedFor() {
        auto rx = makeReceiver("nmea");
        rx->advance(5.5);
        rx->takeOutput();
        // Without a checksum the receiver ignores the line (NMEA requires one).
        rx->receive("$GPGPQ,GLL\r\n");
        QCOMPARE(summarize(rx->takeOutput(), "nmea").byType.count("GLL"), std::size_t(0));
        const std::string q = buildSentence("GPGPQ,GLL") + "\r\n";
        rx->receive(q);
        const auto s = summarize(rx->takeOutput(), "nmea");
        QCOMPARE(s.byType.count("GLL") ? s.byType.at("GLL") : 0, 1);
    }
    void aMismatchedLineSeesNoSentencesAndIsNotHeard() {
        auto rx = makeReceiver("nmea");
        rx->setLineBaud(4800);
        QVERIFY(rx->baudMismatch());
        rx->advance(3);
        const std::string garbage = rx->takeOutput();
        QVERIFY(garbage.size() > 100);
        QVERIFY(garbage.find('$') == std::string::npos);
        QCOMPARE(summarize(garbage).lines.size(), std::size_t(0));
        rx->setLineBaud(9600);
        rx->advance(1);
        QVERIFY(summarize(rx->takeOutput()).byType.count("GGA"));
    }
    void sameSeedGivesTheSameBytes() {
        SimOptions o;
        o.seed = 77;
        auto a = makeReceiver("nmea", o), b = makeReceiver("nmea", o);
        a->advance(20);
        b->advance(7);
        b->advance(13);
        QCOMPARE(a->takeOutput(), b->takeOutput());
        o.seed = 78;
        auto c = makeReceiver("nmea", o);
        c->advance(20);
        o.seed = 77;
        auto d = makeReceiver("nmea", o);
        d->advance(20);
        QVERIFY(d->takeOutput() != c->takeOutput());
    }
};

QTEST_APPLESS_MAIN(TstSimNmeaReceiver)
#include "tst_sim_nmea_receiver.moc"
