// The exit-status contract of docs/cli.md as a table: every gnss-cli command run through each of
// its outcomes, with the status it must end with and the words it must say on standard error.
//   0 done as asked;
//   1 the source, file or receiver failed (cannot open, no data within --duration, a command
//     refused or unanswered, a value that did not verify);
//   2 the request itself is wrong (usage, unknown key, value out of range, malformed sentence,
//     an action, device or mountpoint that is not there), and nothing was sent.
// (130/143, an interruption, is tst_cli_conventions' interruptedMonitorAndRecord... test.)
// The sources are the in-process simulators (--sim), files this suite writes, a TCP server that
// never speaks, a port nobody listens on, and a test NTRIP caster fed with the simulated base's
// RTCM; each row's placeholders (%LOG%, %SILENT% ...) name them.
#include "cli_run.h"
#include "local_port.h"
#include "ntrip_cli_run.h"
#include "rtcm_fixtures.h"
#include "test_caster.h"

#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

namespace {

using gnss::test::Run;

const QByteArray kNmea = "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,"
                         "0014.4,M,000.6,0100*46\r\n";
// The same sentence without its checksum: nothing in a log of these can be trusted.
const QByteArray kNoChecksum = "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,"
                               "M,0014.4,M,000.6,0100\r\n";

QByteArray nvsProfile(const QByteArray &values) {
    return R"({"format":"gnss-workbench-settings","version":1,"dialect":"nvs","values":{)" +
           values + "}}";
}

} // namespace

class TstCliExitStatus : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    QTcpServer silent_; // accepts, and never says a word
    quint16 closed_ = 0;
    corrections_test::TstCaster caster_;
    QList<QByteArray> rtcm_ = corrections_test::baseEpochs(3);
    int fed_ = 0;

    QString write(const QString &name, const QByteArray &bytes) {
        QFile f(dir_.filePath(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) return {};
        return f.fileName();
    }

    QString expand(QString arg) const {
        const QString host = QStringLiteral("127.0.0.1:%1");
        return arg.replace("%DIR%", dir_.path())
                .replace("%SILENT%", host.arg(silent_.serverPort()))
                .replace("%CLOSED%", host.arg(closed_))
                .replace("%CASTER%", host.arg(caster_.port()));
    }

    // gnss-cli run to its end while this thread's event loop serves the silent server and the
    // caster (which sends an epoch of RTCM to its streaming clients every 100 ms).
    Run run(const QStringList &args, const QByteArray &input) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("TEST_NTRIP_PW", QString::fromUtf8(caster_.password));
        return gnss::test::runCliServing(args, input, env, [this] {
            if (caster_.streamingClients() > 0) caster_.send(rtcm_[fed_++ % rtcm_.size()]);
        });
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QVERIFY(silent_.listen(QHostAddress::LocalHost));
        closed_ = gnss::test::closedPort();
        QVERIFY(caster_.listen());
        QVERIFY(!write("plain.nmea", kNmea.repeated(3)).isEmpty());
        QVERIFY(!write("nochecksum.nmea", kNoChecksum.repeated(3)).isEmpty());
        QVERIFY(!write("empty.nmea", {}).isEmpty());
        QVERIFY(!write("base.rtcm", rtcm_.join()).isEmpty());
        QVERIFY(!write("malformed.json", "rtk.ELGPS=12\n").isEmpty());
        // The simulated NV08C-RTK starts at the defaults: a profile of one of them agrees with
        // it, one of another value differs.
        QVERIFY(!write("same.json", nvsProfile(R"("rtk.ELGPS":"5")")).isEmpty());
        QVERIFY(!write("differs.json", nvsProfile(R"("rtk.ELGPS":"33")")).isEmpty());
    }

    void everyCommandThroughItsOutcomes_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("words"); // said on standard error (empty: not checked)
        auto row = [](const char *name, const QStringList &args, int status,
                      const QString &words = {}, const QByteArray &input = {}) {
            QTest::newRow(name) << args << input << status << words;
        };
        const QString log = "%DIR%/plain.nmea", missing = "/nonexistent/log.nmea";

        for (const char *c : {"decode", "epochs", "stats", "summary"}) {
            const QByteArray name(c);
            row(name + ": a log", {c, log}, 0);
            row(name + ": standard input", {c, "-"}, 0, {}, kNmea);
            row(name + ": a missing file", {c, missing}, 1, missing);
            row(name + ": two files", {c, log, log}, 2);
            row(name + ": an unknown dialect", {c, "--dialect", "garmin", log}, 2, "garmin");
        }
        row("summary: a log without checksums", {"summary", "%DIR%/nochecksum.nmea"}, 0,
            "none of its 3 sentences has a checksum (--lenient decodes them anyway)");
        row("summary: a range that is none", {"summary", "--from", "soon", log}, 2, "soon");

        row("export: a log", {"export", "--format", "gpx", log, "-o", "%DIR%/a.gpx"}, 0);
        row("export: standard input", {"export", "--format", "csv", "-", "-o", "-"}, 0, {}, kNmea);
        row("export: a missing file", {"export", "--format", "gpx", missing, "-o", "%DIR%/b.gpx"},
            1, missing);
        row("export: nothing to export",
            {"export", "--format", "gpx", "%DIR%/empty.nmea", "-o", "%DIR%/c.gpx"}, 1,
            "nothing to export");
        row("export: OUT not writable",
            {"export", "--format", "gpx", log, "-o", "/nonexistent/dir/a.gpx"}, 1,
            "/nonexistent/dir/a.gpx");
        row("export: an unknown format", {"export", "--format", "pdf", log, "-o", "%DIR%/d"}, 2,
            "pdf");
        row("export: no OUT", {"export", "--format", "gpx", log}, 2);

        row("play: to a pseudo-terminal", {"play", log, "--pty", "--speed", "1000"}, 0);
        row("play: a missing file", {"play", missing, "--pty"}, 1, missing);
        row("play: nowhere to play to", {"play", log}, 2, "--pty");
        row("play: two places", {"play", log, "--pty", "--tcp", "1"}, 2, "not 2 of them");

        row("schema: a dialect", {"schema", "nvs"}, 0);
        row("schema: no such dialect", {"schema", "garmin"}, 2, "garmin");
        row("schema: no dialect", {"schema"}, 2);
        row("schema: two dialects", {"schema", "nvs", "geostar"}, 2, "unexpected argument");

        row("encode: a setting", {"encode", "nvs", "PVTRATE=5"}, 0);
        row("encode: a query", {"encode", "nvs", "--query", "rtk.ELGPS"}, 0);
        row("encode: an unknown key", {"encode", "nvs", "PVTRAT=5"}, 2,
            "did you mean rtk.PVTRATE?");
        row("encode: a value out of range", {"encode", "nvs", "rtk.PVTRATE=7"}, 2, "1, 2, 5, 10");
        row("encode: not KEY=VALUE", {"encode", "nvs", "PVTRATE"}, 2, "expected KEY=VALUE");

        row("ports: listed", {"ports"}, 0);
        row("ports: an argument", {"ports", "extra"}, 2, "unexpected argument 'extra'");

        row("probe: a receiver", {"probe", "--sim", "geostar"}, 0);
        row("probe: a missing port", {"probe", "--port", "/dev/ttyGNSSWorkbenchNoSuch"}, 1,
            "/dev/ttyGNSSWorkbenchNoSuch");
        row("probe: nobody listening", {"probe", "--tcp", "%CLOSED%"}, 1, "Connection refused");
        row("probe: no source", {"probe"}, 2, "give one source");
        row("probe: an argument", {"probe", "--sim", "nvs", "extra"}, 2, "unexpected argument");

        row("monitor: a receiver", {"monitor", "--sim", "nvs", "--duration", "1"}, 0);
        row("monitor: a replay", {"monitor", "--replay", log, "--fast"}, 0);
        row("monitor: a replay of no NMEA", {"monitor", "--replay", "%DIR%/empty.nmea", "--fast"},
            1, "no NMEA found");
        row("monitor: a silent source", {"monitor", "--tcp", "%SILENT%", "--duration", "1"}, 1,
            "no data received from 127.0.0.1:");
        row("monitor: nobody listening", {"monitor", "--tcp", "%CLOSED%", "--duration", "1"}, 1,
            "no data received from 127.0.0.1:");
        row("monitor: a missing port", {"monitor", "--port", "/dev/ttyGNSSWorkbenchNoSuch"}, 1,
            "/dev/ttyGNSSWorkbenchNoSuch");
        row("monitor: several sources",
            {"monitor", "--sim", "nvs", "--sim", "nmea", "--duration", "1"}, 0);
        row("monitor: one silent among several",
            {"monitor", "--sim", "nvs", "--tcp", "%SILENT%", "--duration", "1"}, 1,
            "no data received from 127.0.0.1:");
        row("monitor: a malformed one among several", {"monitor", "--sim", "nvs", "--tcp", "b"}, 2,
            "--tcp takes HOST:PORT");
        row("monitor: no source", {"monitor"}, 2, "give one source");
        row("monitor: several at a speed that is none",
            {"monitor", "--sim", "nvs", "--sim", "nmea", "--baud", "fast"}, 2, "--baud expects");
        row("monitor: an argument", {"monitor", "--sim", "nvs", "extra"}, 2, "unexpected argument");

        row("record: a receiver",
            {"record", "--sim", "nvs", "--out", "%DIR%/r.nmea", "--duration", "1"}, 0);
        row("record: a silent source",
            {"record", "--tcp", "%SILENT%", "--out", "%DIR%/s.nmea", "--duration", "1"}, 1,
            "no data received from 127.0.0.1:");
        row("record: OUT not writable", {"record", "--sim", "nvs", "--out", "/nonexistent/d/r"}, 1,
            "/nonexistent/d/r");
        row("record: no OUT", {"record", "--sim", "nvs"}, 2, "--out");
        row("record: several into a folder",
            {"record", "--sim", "nvs", "--sim", "nmea", "--out", "%DIR%/bench", "--duration", "1"},
            0, "%DIR%/bench/sim_nmea.nmea");

        row("send: accepted", {"send", "--sim", "nvs", "PNVGVER"}, 0);
        row("send: unanswered", {"send", "--sim", "nvs", "--timeout", "0.2", "$PNVGRZA,9,1,1"}, 1);
        row("send: a missing port", {"send", "--port", "/dev/ttyGNSSWorkbenchNoSuch", "PNVGVER"}, 1,
            "/dev/ttyGNSSWorkbenchNoSuch");
        row("send: not NMEA", {"send", "--sim", "nvs", "hello world"}, 2, "hello world");
        row("send: a wrong checksum", {"send", "--sim", "nvs", "$PNVGVER*00"}, 2, "checksum");

        const QStringList nvs{"config", "--sim", "nvs"};
        row("config get: keys", nvs + QStringList{"get", "ELGPS"}, 0);
        row("config get: an unknown key", nvs + QStringList{"get", "NOSUCH"}, 2, "NOSUCH");
        row("config get: a missing port",
            {"config", "--port", "/dev/ttyGNSSWorkbenchNoSuch", "get"}, 1,
            "/dev/ttyGNSSWorkbenchNoSuch");
        row("config set: verified", nvs + QStringList{"set", "PVTRATE=2"}, 0);
        row("config set: out of range", nvs + QStringList{"set", "rtk.PVTRATE=7"}, 2,
            "nothing was sent");
        row("config set: an unknown key", nvs + QStringList{"set", "NOSUCH=1"}, 2, "NOSUCH");
        row("config set: ambiguous", nvs + QStringList{"set", "baud=9600"}, 2, "port.COM1.baud");
        row("config export: written", nvs + QStringList{"export", "%DIR%/exported.json"}, 0);
        row("config export: not writable", nvs + QStringList{"export", "/nonexistent/d/p.json"}, 1,
            "/nonexistent/d/p.json");
        row("config apply: a profile", nvs + QStringList{"apply", "%DIR%/differs.json"}, 0);
        row("config apply: a missing file", nvs + QStringList{"apply", "/nonexistent/p.json"}, 1,
            "cannot read /nonexistent/p.json");
        row("config apply: not a profile", nvs + QStringList{"apply", "%DIR%/malformed.json"}, 2,
            "not a settings profile");
        row("config diff: the same", nvs + QStringList{"diff", "%DIR%/same.json"}, 0);
        row("config diff: differences", nvs + QStringList{"diff", "%DIR%/differs.json"}, 1);
        row("config action: done", nvs + QStringList{"action", "save"}, 0);
        row("config action: not this receiver's", {"config", "--sim", "nemerix", "action", "save"},
            2);
        row("config action: no such action", nvs + QStringList{"action", "frobnicate"}, 2,
            "unknown action");

        row("rtcm: a file", {"rtcm", "%DIR%/base.rtcm"}, 0);
        row("rtcm: standard input", {"rtcm", "-"}, 0, {}, kNmea);
        row("rtcm: a missing file", {"rtcm", missing}, 1, missing);
        row("rtcm: two files", {"rtcm", log, log}, 2);

        row("compare: two logs", {"compare", log, log, "--json"}, 0);
        row("compare: two receivers",
            {"compare", "--sim", "nvs", "--sim", "nmea", "--duration", "2"}, 0,
            "epochs matched on UTC time");
        row("compare: nothing in common", {"compare", log, "%DIR%/empty.nmea"}, 1,
            "nothing compared");
        row("compare: a missing file", {"compare", log, missing}, 1, missing);
        row("compare: one source", {"compare", log}, 2, "two sources or more");
        row("compare: a malformed source", {"compare", log, "--tcp", "nohost"}, 2, "--tcp");

        const QStringList caster{"ntrip",         "--caster",        "%CASTER%",
                                 "--user",        "rover7",          "--password-env",
                                 "TEST_NTRIP_PW", "--ntrip-version", "1"};
        row("ntrip: receiving", caster + QStringList{"--mount", "MOUNT", "--duration", "1"}, 0,
            "Receiving RTCM from");
        row("ntrip: an unknown mountpoint", caster + QStringList{"--mount", "NOSUCH"}, 2,
            "Mountpoint NOSUCH is not on");
        row("ntrip: nobody listening",
            {"ntrip", "--caster", "%CLOSED%", "--mount", "M", "--duration", "1"}, 1,
            "no RTCM received");
        row("ntrip: no mountpoint", {"ntrip", "--caster", "%CASTER%"}, 2);
        row("ntrip: an argument", caster + QStringList{"--mount", "MOUNT", "extra"}, 2,
            "unexpected argument 'extra'");
    }
    void everyCommandThroughItsOutcomes() {
        QFETCH(QStringList, args);
        QFETCH(QByteArray, input);
        QFETCH(int, status);
        QFETCH(QString, words);
        for (QString &a : args) a = expand(a);
        const Run r = run(args, input);
        const QByteArray why = "gnss-cli " + args.join(' ').toUtf8() + "\nexit " +
                               QByteArray::number(r.exitCode) + "\nstdout: " + r.out.left(2000) +
                               "\nstderr: " + r.err;
        QVERIFY2(r.status == QProcess::NormalExit, why.constData());
        QVERIFY2(r.exitCode == status, why.constData());
        QVERIFY2(words.isEmpty() || r.err.contains(expand(words).toUtf8()), why.constData());
        // Whatever went wrong is said on standard error.
        QVERIFY2(status == 0 || !r.err.trimmed().isEmpty(), why.constData());
    }

    // "Nothing was sent": a wrong request never reaches the receiver. The listening server sees
    // no byte of a malformed send, an unknown key's set or an out-of-range value's set.
    void aWrongRequestSendsNothing_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("send: not NMEA") << QStringList{"send", "hello world"};
        QTest::newRow("send: a wrong checksum") << QStringList{"send", "$PNVGVER*00"};
        QTest::newRow("config set: an unknown key")
                << QStringList{"config", "--dialect", "nvs", "set", "NOSUCH=1"};
    }
    void aWrongRequestSendsNothing() {
        QFETCH(QStringList, args);
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        QByteArray received;
        connect(&server, &QTcpServer::newConnection, this, [&] {
            QTcpSocket *s = server.nextPendingConnection();
            connect(s, &QTcpSocket::readyRead, this, [&, s] { received += s->readAll(); });
        });
        args.insert(1, "--tcp");
        args.insert(2, QString("127.0.0.1:%1").arg(server.serverPort()));
        const Run r = run(args, {});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(received, QByteArray());
    }
};

QTEST_GUILESS_MAIN(TstCliExitStatus)
#include "tst_cli_exit_status.moc"
