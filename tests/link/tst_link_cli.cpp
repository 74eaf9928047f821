// gnss-cli's link commands end to end against gnss-sim on pseudo-terminals: probe finds each
// simulated receiver at a baud it is not told, send reports outcomes (and refuses a malformed
// sentence before sending anything), record + monitor --replay give back what was received,
// also after the recorder was killed with SIGKILL; config get reads gnss-sim --tcp.
#include "bad_input_files.h"
#include "cli_run.h"
#include "dialect_rows.h"
#include "sim_tcp_process.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>

using gnss::link::test::SimProcess;
using gnss::link::test::SimTcpProcess;

namespace {

using gnss::test::Run;

Run cli(const QStringList &args) {
    return gnss::test::runCli(args, {}, 30000);
}

} // namespace

class TstLinkCli : public QObject {
    Q_OBJECT
private slots:
    void probeFindsEachReceiverAtAnUnknownBaud_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<int>("baud");
        // Every simulated family, each at a rate it supports other than its own, the rates
        // varied from row to row.
        constexpr int kRates[] = {57600, 19200, 4800, 38400};
        int row = 0;
        for (std::string_view id : gnss::sim::builtinSimulators().dialects()) {
            const gnss::Dialect *d = gnss::test::builtinRegistry().find(id);
            QVERIFY(d);
            int baud = 0;
            for (int k = 0; k < 4 && !baud; ++k) {
                const int r = kRates[(row + k) % 4];
                const bool supported = d->supportedBauds.empty() ||
                                       std::find(d->supportedBauds.begin(), d->supportedBauds.end(),
                                                 r) != d->supportedBauds.end();
                if (r != d->defaultBaud && supported) baud = r;
            }
            ++row;
            const std::string name(id);
            QTest::newRow(name.c_str()) << QString::fromStdString(name) << baud;
        }
    }
    void probeFindsEachReceiverAtAnUnknownBaud() {
        QFETCH(QString, dialect);
        QFETCH(int, baud);
        SimProcess sim({"--dialect", dialect, "--baud", QString::number(baud)});
        REQUIRE_SIM(sim);
        const Run r = cli({"probe", "--port", sim.device});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value("baud").toInt(), baud);
        QCOMPARE(o.value("dialect").toString(), dialect);
        if (dialect != "nmea") QVERIFY2(!o.value("firmware").toString().isEmpty(), r.out);
    }

    // config over TCP: gnss-sim --tcp listens on 127.0.0.1, the dialect is found on the link.
    void configGetReadsAReceiverOverTcp_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::newRow("nvs") << "nvs"
                             << "rtk.MODE"
                             << "2";
    }
    void configGetReadsAReceiverOverTcp() {
        QFETCH(QString, dialect);
        QFETCH(QString, key);
        QFETCH(QString, value);
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimTcpProcess sim({"--dialect", dialect});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        const Run r = cli({"config", "--tcp", sim.address, "get", key});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value("dialect").toString(), dialect);
        QCOMPARE(o.value("values").toObject().value(key).toString(), value);
    }

    void malformedSentenceIsRefusedBeforeAnythingIsSent() {
        const Run r = cli({"send", "--port", "/dev/null-no-such-port", "PNVGVER", "PN$VG"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
        QVERIFY(!r.err.contains("Cannot open")); // the port was never opened
        // Not an address, a checksum that is not one, a wrong one: each refused with its cause.
        for (const auto &[typed, cause] :
             {std::pair<QString, QByteArray>{"hello world", "is not upper-case letters"},
              {"PNVG*ZZ", "not two hex digits"},
              {"$PNVGVER*00", "it is *4E"}}) {
            const Run bad = cli({"send", "--port", "/dev/null-no-such-port", typed});
            QVERIFY2(bad.exitCode == 2, bad.err.constData());
            QVERIFY2(bad.err.contains(cause) && bad.err.contains("nothing was sent"),
                     bad.err.constData());
            QVERIFY(!bad.err.contains("Cannot open"));
        }
    }

    // --fix-checksum: the wrong checksum is replaced, and the replacement said.
    void aWrongChecksumIsFixedWhenAsked() {
        SimProcess sim({"--dialect", "nvs"});
        REQUIRE_SIM(sim);
        const Run r = cli({"send", "--port", sim.device, "--baud", "115200", "--fix-checksum",
                           "$PNVGVER*00"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("checksum *00 replaced by *4E"), r.err.constData());
        QCOMPARE(QJsonDocument::fromJson(r.out.trimmed()).object().value("sentence").toString(),
                 QStringLiteral("$PNVGVER*4E"));
    }

    void sendPrintsRepliesAndOutcomes() {
        SimProcess sim({"--dialect", "nvs"});
        REQUIRE_SIM(sim);
        const Run r = cli({"send", "--port", sim.device, "--baud", "115200", "PNVGVER",
                           "$PNVGRTK,PVTRATE,99"});
        QCOMPARE(r.exitCode, 1); // one refused
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        const QJsonObject first = QJsonDocument::fromJson(lines[0]).object();
        QCOMPARE(first.value("sentence").toString(), QStringLiteral("$PNVGVER*4E"));
        QCOMPARE(first.value("outcome").toString(), QStringLiteral("accepted"));
        QVERIFY(first.value("replies").toArray().first().toString().startsWith("$PNVGVER,NVS"));
        QCOMPARE(QJsonDocument::fromJson(lines[1]).object().value("outcome").toString(),
                 QStringLiteral("refused"));
        QVERIFY(r.err.contains("< $PNVGVER,NVS"));
    }

    void recordThenReplayGivesBackTheSameSentences() {
        SimProcess sim({"--dialect", "nmea"});
        REQUIRE_SIM(sim);
        QTemporaryDir dir;
        const QString log = dir.filePath("run.nmea");
        const Run rec = cli({"record", "--port", sim.device, "--out", log, "--duration", "2.5"});
        QVERIFY2(rec.exitCode == 0, rec.err.constData());
        QFile f(log);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        QVERIFY(bytes.size() > 300);
        QVERIFY(QFile::exists(log + ".idx"));

        const Run decoded = cli({"decode", log});
        const Run replayed = cli({"monitor", "--replay", log, "--fast"});
        QVERIFY2(replayed.exitCode == 0, replayed.err.constData());
        QCOMPARE(replayed.out, decoded.out);
        const Run epochs = cli({"monitor", "--replay", log, "--fast", "--epochs"});
        QVERIFY(epochs.out.count('\n') >= 1);
    }

    // Several sources at once: monitor tags each line with its receiver (its place among the
    // sources, and the source as given); record writes one file per receiver into the --out
    // folder, named after it; a receiver whose line drops (the hang-up fault) leaves the other's
    // recording whole.
    void severalSourcesAtOnce() {
        const Run mon =
                cli({"monitor", "--sim", "nvs", "--sim", "geostar", "--epochs", "--duration", "2"});
        QVERIFY2(mon.exitCode == 0, mon.err.constData());
        int seen[2] = {0, 0};
        for (const QByteArray &line : mon.out.trimmed().split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            const int r = o["receiver"].toInt(-1);
            QVERIFY2(r == 0 || r == 1, line.constData());
            QCOMPARE(o["source"].toString(), QString(r == 0 ? "sim nvs" : "sim geostar"));
            QVERIFY(o.contains("fix"));
            ++seen[r];
        }
        QVERIFY(seen[0] > 0 && seen[1] > 0);

        SimProcess a({"--dialect", "nmea", "--baud", "38400"});
        SimProcess b({"--dialect", "nmea", "--baud", "57600", "--faults", "hangup=6/1"});
        REQUIRE_SIM(a);
        REQUIRE_SIM(b);
        QTemporaryDir dir;
        const Run rec = cli({"record", "--port", a.device, "--port", b.device, "--out",
                             dir.filePath("bench"), "--duration", "6"});
        QVERIFY2(rec.exitCode == 0, rec.err.constData());
        QVERIFY2(rec.err.contains("link lost"), rec.err.constData()); // b's line went
        const QString fa = dir.filePath("bench/" + QFileInfo(a.device).fileName() + ".nmea");
        const QString fb = dir.filePath("bench/" + QFileInfo(b.device).fileName() + ".nmea");
        QVERIFY2(QFile::exists(fa) && QFile::exists(fb), rec.err.constData());
        // a's recording is whole: every epoch, none cut.
        const Run decoded = cli({"stats", "--json", fa});
        const QJsonObject stats = QJsonDocument::fromJson(decoded.out).object();
        QVERIFY2(stats["epochs"].toInt() >= 5, decoded.out.constData());
        QCOMPARE(stats["bytes_skipped"].toInt(), 0);
    }

    // monitor --replay of a file that cannot be replayed ends at once with status 1 and says
    // why: a broken index is not retried (it would not mend), a file that is not NMEA is named.
    void aReplayThatCannotBeReadEndsSayingWhy_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QByteArray>("index");
        QTest::addColumn<QString>("words");
        const QByteArray gga = gnss::test::kOneGga;
        QTest::newRow("no such file") << QByteArray("-") << QByteArray() << "Cannot read";
        QTest::newRow("a foreign index")
                << gga << QByteArray("<xml>\n") << ".idx, line 1: not an index line";
        QTest::newRow("an index past the data")
                << gga << QByteArray("R 5000 0 9000\n")
                << "line 1: chunk ends past the end of the data file";
        QTest::newRow("not NMEA") << QByteArray("hello world\nno NMEA here\n") << QByteArray()
                                  << "replay of input.log: no NMEA found";
    }
    void aReplayThatCannotBeReadEndsSayingWhy() {
        QFETCH(QByteArray, bytes);
        QFETCH(QByteArray, index);
        QFETCH(QString, words);
        QTemporaryDir dir;
        const QString in = gnss::test::writeUserFile(dir, "input.log", bytes, index);
        QVERIFY(!in.isEmpty());
        QElapsedTimer t;
        t.start();
        const Run r = cli({"monitor", "--replay", in, "--fast"});
        QVERIFY2(r.exitCode == 1, r.err.constData());
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
        QVERIFY2(!r.err.contains("trying again"), r.err.constData());
        QVERIFY2(t.elapsed() < 10000, QByteArray::number(t.elapsed()));
    }

    // kill -9 in the middle of a recording: what arrived up to the kill is on disk (the data
    // and its index are flushed with every chunk), and the log opens again: the index's torn
    // last line is skipped and the data after the last indexed chunk becomes one more chunk.
    void aRecordingSurvivesKill9() {
        SimProcess sim({"--dialect", "nmea"});
        REQUIRE_SIM(sim);
        QTemporaryDir dir;
        const QString log = dir.filePath("killed.nmea");
        QProcess rec;
        rec.start(QStringLiteral(GNSS_CLI_PATH), {"record", "--port", sim.device, "--out", log});
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(log).size() > 500, 20000);
        QTest::qWait(1000);
        QFile f(log);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray before = f.readAll(); // some time before the kill
        f.close();
        // More has come since (waited for, not timed: a slow or sanitized build may take longer
        // than a second to write the next epoch).
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(log).size() > before.size(), 20000);
        rec.kill(); // SIGKILL: no chance to flush or close anything
        QVERIFY(rec.waitForFinished(5000));
        QCOMPARE(rec.exitStatus(), QProcess::CrashExit);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray after = f.readAll();
        f.close();
        QVERIFY(after.startsWith(before));     // nothing written was lost
        QVERIFY(after.size() > before.size()); // and the last second is there too
        // The index as a kill in the middle of its write leaves it: a torn last line.
        QFile index(log + ".idx");
        QVERIFY(index.open(QIODevice::Append));
        index.write("R 99999 ");
        index.close();
        const Run decoded = cli({"decode", log});
        const Run replayed = cli({"monitor", "--replay", log, "--fast"});
        QVERIFY2(replayed.exitCode == 0, replayed.err.constData());
        QCOMPARE(replayed.out, decoded.out); // every byte recorded plays back
        QVERIFY(decoded.out.count('\n') > 5);
    }
};

QTEST_GUILESS_MAIN(TstLinkCli)
#include "tst_link_cli.moc"
