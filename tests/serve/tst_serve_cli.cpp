// gnss-cli serve end to end: usage errors exit 2 before anything listens, a port in use exits
// 1; gnss-sim --rtcm-base served as an NTRIP caster to gnss-cli ntrip and to RTKLIB's str2str
// (Debian's, when installed) with a password; the raw port; a recorded RTCM file replayed from
// the first client on. Every server on 127.0.0.1, every process stopped by the test.
#include "cli_run.h"
#include "local_port.h"
#include "rtcm/rtcm_framer.h"
#include "rtcm_fixtures.h"
#include "serve_process.h"
#include "sim_tcp_process.h"
#include "str2str_process.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using gnss::link::test::SimTcpProcess;
using gnss::test::Run;
using gnss::test::ServeProcess;

namespace {

QProcessEnvironment withPassword() {
    auto env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PW"), QStringLiteral("s3cret-pw"));
    env.insert(QStringLiteral("EMPTY"), QString());
    return env;
}

// `gnss-cli serve ARGS` with the passwords above in its environment.
struct Serve : ServeProcess {
    explicit Serve(const QStringList &args) : ServeProcess(args, withPassword()) {}
};

// Connects to 127.0.0.1:port, sends `request` and reads until `done` says so (or 8 s pass).
QByteArray readFrom(quint16 port, const QByteArray &request,
                    const std::function<bool(const QByteArray &)> &done) {
    QTcpSocket s;
    s.connectToHost(QStringLiteral("127.0.0.1"), port);
    if (!s.waitForConnected(3000)) return {};
    s.write(request);
    QByteArray got;
    QElapsedTimer t;
    t.start();
    while (!done(got) && t.elapsed() < 8000) {
        s.waitForReadyRead(200);
        got += s.readAll();
    }
    return got;
}

gnss::rtcm::RtcmFramerStats framed(const QByteArray &bytes) {
    gnss::rtcm::RtcmFramer f;
    f.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
           [](const gnss::rtcm::RtcmFrame &) {});
    f.finish([](const gnss::rtcm::RtcmFrame &) {});
    return f.stats();
}

// gnss-sim's base station as mountpoint BASE, for user u with the password in PW.
QStringList baseServed(const SimTcpProcess &base) {
    return {"--tcp", base.address,     "--ntrip", "127.0.0.1:0/BASE", "--user",
            "u",     "--password-env", "PW",      "--duration",       "15"};
}

#define REQUIRE_BASE(base)                                                                         \
    do {                                                                                           \
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");                 \
        if (!(base).ok()) QSKIP(qPrintable("gnss-sim did not start: " + (base).error));            \
    } while (0)

} // namespace

class TstServeCli : public QObject {
    Q_OBJECT
private slots:
    void usageErrorsListenNowhere_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("words");
        QTest::newRow("neither --ntrip nor --raw")
                << QStringList{"--sim", "nmea"} << "give --ntrip";
        QTest::newRow("no source") << QStringList{"--raw", "0"} << "give one source";
        QTest::newRow("no mountpoint")
                << QStringList{"--sim", "nmea", "--ntrip", "127.0.0.1:0/"} << "[ADDR:]PORT/MOUNT";
        QTest::newRow("a mountpoint with '?'")
                << QStringList{"--sim", "nmea", "--ntrip", "0/A?B"} << "cannot hold '?'";
        QTest::newRow("a port out of range")
                << QStringList{"--sim", "nmea", "--ntrip", "70000/BASE"} << "is not a port";
        QTest::newRow("an address that is none")
                << QStringList{"--sim", "nmea", "--raw", "example.org:5000"} << "not an IP address";
        QTest::newRow("--user without --password-env")
                << QStringList{"--sim", "nmea", "--ntrip", "0/BASE", "--user", "u"}
                << "go together";
        QTest::newRow("an empty password variable")
                << QStringList{"--sim",  "nmea", "--ntrip",        "0/BASE",
                               "--user", "u",    "--password-env", "EMPTY"}
                << "EMPTY is not set or empty";
        QTest::newRow("--loop without --replay")
                << QStringList{"--sim", "nmea", "--raw", "0", "--loop"} << "--loop goes with";
    }
    void usageErrorsListenNowhere() {
        QFETCH(QStringList, args);
        QFETCH(QString, words);
        const Run r =
                gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH), QStringList{"serve"} + args,
                                       {}, 10000, withPassword());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
        QVERIFY(!r.err.contains("listen"));
    }

    void aPortInUseFails() {
        QTcpServer taken;
        QVERIFY(taken.listen(QHostAddress::LocalHost));
        const Run r = gnss::test::runProgram(
                QStringLiteral(GNSS_CLI_PATH),
                {"serve", "--sim", "nmea", "--ntrip",
                 QStringLiteral("127.0.0.1:%1/BASE").arg(taken.serverPort())},
                {}, 10000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("cannot listen on 127.0.0.1:"), r.err.constData());
    }

    void gnssCliNtripReceivesTheBase() {
        SimTcpProcess base({"--rtcm-base"});
        REQUIRE_BASE(base);
        Serve serve(baseServed(base));
        const quint16 port = serve.ntripPort();
        QVERIFY2(port != 0, serve.err.constData());
        QVERIFY(!serve.err.contains("reachable from other machines"));
        const QString caster = QStringLiteral("127.0.0.1:%1").arg(port);
        const Run r =
                gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH),
                                       {"ntrip", "--caster", caster, "--mount", "BASE", "--user",
                                        "u", "--password-env", "PW", "--duration", "3"},
                                       {}, 10000, withPassword());
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QSet<int> types;
        for (const QJsonObject &o : gnss::test::jsonLines(r.out)) types << o["type"].toInt();
        QVERIFY2(types.contains(1074) && types.contains(1084) && types.contains(1005),
                 r.out.left(400).constData());
        QVERIFY(!serve.err.contains("s3cret-pw"));
        // The source table says what is served, without a password.
        const Run t =
                gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH),
                                       {"ntrip", "--caster", caster, "--sourcetable"}, {}, 10000);
        QVERIFY2(t.exitCode == 0, t.err.constData());
        const QJsonObject str = gnss::test::jsonLines(t.out).value(0);
        QCOMPARE(str["mountpoint"].toString(), QStringLiteral("BASE"));
        QVERIFY2(str["format_details"].toString().contains("1074(1)"), t.out.constData());
        QCOMPARE(str["nav_system"].toString(), QStringLiteral("GPS+GLO"));
        QCOMPARE(str["authentication"].toString(), QStringLiteral("B"));
        QVERIFY(std::abs(str["latitude"].toDouble() - 55.75) < 0.01);
        // A wrong password is refused.
        auto env = withPassword();
        env.insert(QStringLiteral("PW"), QStringLiteral("wrong"));
        const Run w =
                gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH),
                                       {"ntrip", "--caster", caster, "--mount", "BASE", "--user",
                                        "u", "--password-env", "PW", "--duration", "3"},
                                       {}, 10000, env);
        QCOMPARE(w.exitCode, 1);
        QVERIFY2(w.err.contains("401"), w.err.constData());
        QVERIFY(!serve.waitFor("refused \\(401\\)", 3000).isEmpty());
    }

    void str2strReceivesCrcValidRtcm() {
        const QString str2str = QStandardPaths::findExecutable(QStringLiteral("str2str"));
        if (str2str.isEmpty()) QSKIP("str2str (Debian package rtklib) is not installed");
        SimTcpProcess base({"--rtcm-base"});
        REQUIRE_BASE(base);
        Serve serve(baseServed(base));
        const quint16 port = serve.ntripPort();
        QVERIFY2(port != 0, serve.err.constData());
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("out.rtcm"));
        QProcess rtk;
        rtk.setProcessChannelMode(QProcess::MergedChannels);
        rtk.start(str2str,
                  {"-in", QStringLiteral("ntrip://u:s3cret-pw@127.0.0.1:%1/BASE").arg(port), "-out",
                   "file://" + out});
        QVERIFY(rtk.waitForStarted(5000));
        QVERIFY2(!serve.waitFor("receives BASE \\(user u\\)", 8000).isEmpty(),
                 serve.err.constData());
        QTest::qWait(3500);
        gnss::test::stopStr2str(rtk);
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const gnss::rtcm::RtcmFramerStats s = framed(f.readAll());
        QVERIFY2(s.frames >= 6, qPrintable(QString::number(s.frames)));
        QCOMPARE(s.crcFailures, 0u);
        // Nothing but whole frames (and the blank line after ICY 200 OK, which str2str keeps).
        QVERIFY2(s.bytesSkipped <= 2, qPrintable(QString::number(s.bytesSkipped)));
    }

    void theRawPortPassesEveryByte() {
        Serve serve({"--sim", "nmea", "--raw", "127.0.0.1:0", "--duration", "10"});
        const quint16 port =
                quint16(serve.waitFor("raw stream on 127\\.0\\.0\\.1:(\\d+)").toUInt());
        QVERIFY2(port != 0, serve.err.constData());
        const QByteArray got = readFrom(port, "ignored\r\n", [](const QByteArray &g) {
            return g.contains("$GPGGA") || g.contains("$GNGGA");
        });
        QVERIFY2(got.contains("GGA,"), got.left(300).constData());
        QVERIFY(!serve.waitFor("raw client 127\\.0\\.0\\.1:\\d+ connected", 3000).isEmpty());
    }

    void aRecordedFileIsServedFromTheFirstClient() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("base.rtcm"));
        QByteArray all;
        for (const QByteArray &e : corrections_test::baseEpochs(3)) all += e;
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(all);
        f.close();
        Serve serve({"--replay", path, "--ntrip", "127.0.0.1:0/BASE", "--duration", "15"});
        const quint16 port = serve.ntripPort();
        QVERIFY2(port != 0, serve.err.constData());
        QTest::qWait(1500); // nothing is played before a client comes
        const QByteArray got =
                readFrom(port, "GET /BASE HTTP/1.0\r\nUser-Agent: NTRIP test\r\n\r\n",
                         [&](const QByteArray &g) { return g.endsWith(all); });
        QCOMPARE(got, "ICY 200 OK\r\n\r\n" + all);
        QVERIFY(serve.proc.waitForFinished(5000)); // the end of the file ends it
        QCOMPARE(serve.proc.exitCode(), 0);
    }
};

QTEST_GUILESS_MAIN(TstServeCli)
#include "tst_serve_cli.moc"
