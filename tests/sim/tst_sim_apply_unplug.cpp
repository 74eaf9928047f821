// The receiver unplugged in the middle of a settings apply (docs/reliability.md, "Faults, end to
// end"). First the simulator's side alone (hangupon=CMD: the line drops the moment CMD arrives,
// the receiver carries it out, its answer is lost). Then end to end: the settings engine on a
// Connection to gnss-sim, the line dropping at a chosen command of a seven-command apply of six
// NV08C settings, on a pseudo-terminal (through the real QSerialPort, reconnecting by the --link
// name) and over TCP (gnss-sim drops the client and refuses connections while down, as a
// serial-to-Ethernet server does; the TcpTransport reconnects). Each command has its outcome
// (answered, sent with the answer lost, not sent); no setting is verified before a read-back;
// when the link is back the engine reads the apply's settings back by itself and then has the
// receiver's values.
#include "builtin_registry.h"
#include "sim/dialect_receiver.h"
#include "sim/faults.h"
#include "sim_line.h"

#include "config/settings_engine.h"
#include "link/connection.h"

#include "core/sentence_builder.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::config;
using namespace gnss::link;
using gnss::link::test::SimLine;

namespace {

std::unique_ptr<sim::Receiver> receiverWith(std::string_view faults) {
    std::string error;
    sim::SimOptions o;
    o.faults = *sim::parseFaults(faults, error);
    return sim::makeReceiver("nvs", o);
}

// What `rx` sends right after `body` arrives (what it said before is dropped).
std::string answerTo(sim::Receiver &rx, const std::string &body) {
    rx.takeOutput();
    rx.receive(buildSentence(body) + "\r\n");
    rx.advance(0.01);
    return rx.takeOutput();
}

// The apply: six settings, seven commands in this order (gnss-cli encode nvs ...):
// PNVGRTK; PNVGIDL CLEAR, ADD, ADD; PNVGPPS; PNVGRZB PORT,2 and PORT,2,GGA,1 (write-only).
const std::vector<KeyValue> kApply = {
        {"rtk.PVTRATE", "10"},   {"rtk.ELGPS", "10"},        {"idl.stations", "3:0.0720;43:0.0000"},
        {"pps.duration", "500"}, {"pps.cable_delay", "120"}, {"output.COM2", "GGA:1"}};
constexpr int kCommands = 7;

using VerdictMap = QMap<QString, Verdict>;

const char *name(Verdict v) {
    switch (v) {
    case Verdict::Verified: return "Verified";
    case Verdict::Echoed: return "Echoed";
    case Verdict::Refused: return "Refused";
    case Verdict::NotTaken: return "NotTaken";
    case Verdict::NotReported: return "NotReported";
    case Verdict::WrittenUnverified: return "WrittenUnverified";
    case Verdict::NotSent: return "NotSent";
    case Verdict::NotReadBack: return "NotReadBack";
    case Verdict::Unconfirmed: return "Unconfirmed";
    }
    return "?";
}

// Every command and check of a report, for failure messages.
QString describe(const OperationReport &r) {
    QString s = r.title + ": " + r.error;
    for (const auto &c : r.commands)
        s += QString("\n  %1 -> %2 after %3 attempt(s) (%4)")
                     .arg(c.sentence, outcomeName(c.outcome))
                     .arg(c.attempts)
                     .arg(c.detail);
    for (const auto &c : r.checks)
        s += QString("\n  %1 = %2: %3 (reported '%4')")
                     .arg(QString::fromStdString(c.key), QString::fromStdString(c.wanted),
                          name(c.verdict), QString::fromStdString(c.reported));
    return s;
}

// The checks of `r` as key -> verdict.
VerdictMap verdicts(const OperationReport &r) {
    VerdictMap m;
    for (const auto &c : r.checks) m[QString::fromStdString(c.key)] = c.verdict;
    return m;
}

// "ok" answered (or sent, for a command without answer), "lost" sent with its answer lost,
// "unsent" not sent.
QString fateOf(const CommandResult &c) {
    if (c.outcome == CommandOutcome::Accepted || c.outcome == CommandOutcome::Sent) return "ok";
    if (c.outcome == CommandOutcome::LinkLost) return c.attempts > 0 ? "lost" : "unsent";
    return outcomeName(c.outcome);
}

} // namespace

Q_DECLARE_METATYPE(VerdictMap)

class TstSimApplyUnplug : public QObject {
    Q_OBJECT
private slots:
    void theFaultParses() {
        std::string error;
        const auto f = sim::parseFaults("hangupon=PNVGPPS+ADD/0.5", error);
        QVERIFY2(f, error.c_str());
        QCOMPARE(f->hangupOn, (std::vector<std::string>{"PNVGPPS", "ADD"}));
        QCOMPARE(f->hangupOnDown, 0.5);
        QVERIFY(f->hangsUpOn("PNVGIDL", "ADD"));
        QVERIFY(!f->hangsUpOn("PNVGIDL", "CLEAR"));
        QCOMPARE(sim::parseFaults("hangupon=PNVGRTK", error)->hangupOnDown, 1.0);
        QVERIFY(!sim::parseFaults("hangupon=", error));
        QVERIFY(!sim::parseFaults("hangupon=PNVGRTK/0", error));
        QVERIFY(!sim::parseFaults("hangupon=/1", error));
    }
    void theLineDropsAsTheCommandArrivesWhichIsCarriedOut() {
        auto rx = receiverWith("hangupon=PNVGPPS/1");
        const sim::SettingsStore &store = static_cast<sim::DialectReceiver &>(*rx).settings();
        rx->advance(1);
        QVERIFY(answerTo(*rx, "PNVGRTK,PVTRATE,10").find("$PNVGRTK") != std::string::npos);
        QVERIFY(!rx->takeLineDrop());
        // The command and one behind it in the same write: the first is carried out, the line
        // goes, the second is not heard.
        rx->receive(buildSentence("PNVGPPS,,,,,500,,") + "\r\n" +
                    buildSentence("PNVGRTK,PVTRATE,2") + "\r\n");
        QVERIFY(rx->takeLineDrop());
        QVERIFY(!rx->takeLineDrop()); // taken once
        QCOMPARE(store.value("pps.duration"), std::string("500"));
        QCOMPARE(store.value("rtk.PVTRATE"), std::string("10"));
        // Once a run: the receiver hears everything again and the same command keeps the line.
        QVERIFY(answerTo(*rx, "PNVGPPS,,,,,600,,").find("$PNVGPPS") != std::string::npos);
        QVERIFY(!rx->takeLineDrop());
        QCOMPARE(store.value("pps.duration"), std::string("600"));
    }

    void aSettingsApplyTheLineDropsIn_data() {
        QTest::addColumn<QString>("line"); // pty or tcp (sim_line.h)
        QTest::addColumn<QString>("fault");
        QTest::addColumn<QStringList>("fates");   // per command, in order
        QTest::addColumn<VerdictMap>("applied");  // the apply's report
        QTest::addColumn<VerdictMap>("readBack"); // the report of the read-back on return
        const auto V = [](Verdict a, Verdict b, Verdict c, Verdict d) {
            return VerdictMap{{"rtk.PVTRATE", a},  {"rtk.ELGPS", a},       {"idl.stations", b},
                              {"pps.duration", c}, {"pps.cable_delay", c}, {"output.COM2", d}};
        };
        using enum Verdict;
        for (const QString line : {"pty", "tcp"}) {
            const auto row = [&](const char *where) -> QTestData & {
                return QTest::newRow(qPrintable(line + ": " + where)) << line;
            };
            row("at the first command")
                    << "hangupon=PNVGRTK/0.5" << QStringList{"lost",   "unsent", "unsent", "unsent",
                                                             "unsent", "unsent", "unsent"}
                    << V(Unconfirmed, NotSent, NotSent, NotSent)
                    << V(Verified, NotSent, NotSent, NotSent); // carried out, its answer lost
            row("between the sentences of one setting")
                    << "hangupon=ADD/0.5"
                    << QStringList{"ok", "ok", "lost", "unsent", "unsent", "unsent", "unsent"}
                    << V(NotReadBack, Unconfirmed, NotSent, NotSent)
                    << V(Verified, NotTaken, NotSent, NotSent); // one station of the two
            row("in the middle") << "hangupon=PNVGPPS/0.5"
                                 << QStringList{"ok", "ok", "ok", "ok", "lost", "unsent", "unsent"}
                                 << V(NotReadBack, NotReadBack, Unconfirmed, NotSent)
                                 << V(Verified, Verified, Verified, NotSent);
        }
    }
    void aSettingsApplyTheLineDropsIn() {
        QFETCH(QString, line);
        QFETCH(QString, fault);
        QFETCH(QStringList, fates);
        QFETCH(VerdictMap, applied);
        QFETCH(VerdictMap, readBack);
        SimLine sim(line, {"--dialect", "nvs", "--faults", fault});
        REQUIRE_SIM(sim);
        const DialectRegistry &registry = gnss::test::builtinRegistry();
        const Dialect *nvs = registry.find("nvs");
        Connection conn(sim.transport(115200), registry);
        conn.commands()->setDialect(nvs);
        conn.setReconnectDelays(50, 200);
        SettingsEngine engine;
        engine.attach(&conn, nvs);
        QSignalSpy lost(&conn, &Connection::linkLost), back(&conn, &Connection::linkRestored);
        QSignalSpy finished(&engine, &SettingsEngine::finished);
        QVERIFY(conn.open());
        QTRY_VERIFY_WITH_TIMEOUT(conn.transport()->isOpen(), 20000);

        // The apply: the line drops at the command the fault names.
        QVERIFY(engine.apply(kApply));
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() >= 1, 30000);
        const OperationReport a = finished.at(0).at(0).value<OperationReport>();
        const QByteArray aText = describe(a).toUtf8();
        QCOMPARE(int(lost.count()), 1);
        QCOMPARE(a.operation, Operation::Apply);
        QVERIFY2(a.commands.size() == kCommands, aText.constData());
        QStringList got;
        for (const auto &c : a.commands) got << fateOf(c);
        QVERIFY2(got == fates, (aText + "\nfates: " + got.join(' ').toUtf8()).constData());
        QVERIFY2(verdicts(a) == applied, aText.constData());
        QVERIFY(a.readBackOnReturn);
        QVERIFY(!a.ok());
        // Nothing verified, and no old or echoed value passed for the receiver's.
        for (const auto &c : a.checks) {
            QVERIFY2(c.verdict != Verdict::Verified && c.reported.empty(), aText.constData());
            QVERIFY2(!engine.receiverValue(c.key) || c.key == "output.COM2", aText.constData());
        }
        QVERIFY(!engine.pendingReadBack().empty());

        // Back: the engine reads them back by itself; the report sets each against the wanted.
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() >= 2, 30000);
        QCOMPARE(int(back.count()), 1);
        const OperationReport r = finished.at(1).at(0).value<OperationReport>();
        const QByteArray rText = describe(r).toUtf8();
        QCOMPARE(r.operation, Operation::ReadBack);
        QVERIFY2(!r.commands.isEmpty(), rText.constData());
        for (const auto &c : r.commands)
            QVERIFY2(c.outcome == CommandOutcome::Accepted, rText.constData());
        QVERIFY2(verdicts(r) == readBack, rText.constData());
        QVERIFY(!r.readBackOnReturn);
        QVERIFY(engine.pendingReadBack().empty());
        for (const auto &c : r.checks) {
            if (c.key == "output.COM2") { // write-only, not sent: still unknown
                QVERIFY2(!engine.receiverValue(c.key), rText.constData());
                continue;
            }
            // The engine has what the receiver reported; verified means it is the wanted one.
            QVERIFY2(engine.receiverValue(c.key).value_or("") == c.reported, rText.constData());
            QVERIFY2(!c.reported.empty() || c.key == "idl.stations", rText.constData());
            QCOMPARE(c.verdict == Verdict::Verified,
                     engine.changesFrom({{c.key, c.wanted}}).empty());
        }

        // And it agrees with the simulator: a fresh read of them brings the same values.
        std::map<std::string, std::string> seen;
        for (const auto &c : r.checks)
            if (auto v = engine.receiverValue(c.key)) seen[c.key] = *v;
        std::vector<std::string> keys;
        for (const auto &[k, v] : seen) keys.push_back(k);
        QVERIFY(engine.read(keys));
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() >= 3, 30000);
        const OperationReport fresh = finished.at(2).at(0).value<OperationReport>();
        QVERIFY2(fresh.ok(), qPrintable(describe(fresh)));
        for (const auto &[k, v] : seen) QCOMPARE(engine.receiverValue(k).value_or("?"), v);
        QCOMPARE(int(lost.count()), 1); // the fault comes once
    }
};

QTEST_GUILESS_MAIN(TstSimApplyUnplug)
#include "tst_sim_apply_unplug.moc"
