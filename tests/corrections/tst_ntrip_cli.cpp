// gnss-cli ntrip end to end against the caster written in the test: the source table as JSON
// lines with distances, a mountpoint's RTCM as JSON and byte-exact in a file, the nearest
// mountpoint chosen, refusals ending with exit code 1 and the reason, the password taken from
// the environment and never printed.
#include "cli_run.h"
#include "ntrip_cli_run.h"
#include "rtcm_fixtures.h"
#include "sim_process.h"
#include "test_caster.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace corrections_test;

namespace {

using gnss::test::jsonLines;
using gnss::test::Run;

// Runs gnss-cli while the test's event loop keeps serving the caster; `feed` is called every
// 100 ms to push data.
Run cli(const QStringList &args, const std::function<void()> &feed = {},
        const QString &password = QStringLiteral("s3cret-pw")) {
    return gnss::test::runNtripCli(args, password, feed, {}, 20000);
}

// The protocol versions gnss-cli ntrip is asked for, a row each; `second` names the NTRIP 2 row.
void versionRows(const char *second = "NTRIP 2") {
    QTest::addColumn<QString>("version");
    QTest::newRow("NTRIP 1") << "1";
    QTest::newRow(second) << "2";
}

QString casterArg(const TstCaster &c) {
    return QStringLiteral("127.0.0.1:%1").arg(c.port());
}

} // namespace

class TstNtripCli : public QObject {
    Q_OBJECT
private slots:
    void theSourceTableIsPrintedWithDistances_data() { versionRows(); }
    void theSourceTableIsPrintedWithDistances() {
        QFETCH(QString, version);
        TstCaster caster;
        QVERIFY(caster.listen());
        const Run r = cli({"ntrip", "--caster", casterArg(caster), "--sourcetable",
                           "--ntrip-version", version, "--gga", "55.7512,37.6184,150"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QList<QJsonObject> lines = jsonLines(r.out);
        QCOMPARE(lines.size(), 5); // 3 STR, 1 CAS, 1 NET
        QCOMPARE(lines[0].value("type").toString(), QString("STR"));
        QCOMPARE(lines[0].value("mountpoint").toString(), QString("MOUNT"));
        QCOMPARE(lines[0].value("nmea").toBool(), true);
        QCOMPARE(lines[0].value("bitrate").toInt(), 9600);
        QCOMPARE(lines[0].value("distance_km").toDouble(), 0.2);
        QCOMPARE(lines[1].value("distance_km").toDouble(), 632.9);
        QCOMPARE(lines[3].value("type").toString(), QString("CAS"));
        QCOMPARE(lines[4].value("type").toString(), QString("NET"));
        QVERIFY2(r.err.contains("\"streams\":3") && r.err.contains("\"complete\":true"),
                 r.err.constData());
    }

    void aMountpointsRtcmIsPrintedAndWrittenByteExact_data() { versionRows("NTRIP 2, chunked"); }
    void aMountpointsRtcmIsPrintedAndWrittenByteExact() {
        QFETCH(QString, version);
        TstCaster caster;
        QVERIFY(caster.listen());
        QTemporaryDir dir;
        const QString file = dir.filePath("got.rtcm");
        const QList<QByteArray> epochs = baseEpochs(30);
        QByteArray sent;
        int next = 0;
        auto feed = [&] {
            if (caster.streamingClients() == 1 && next < epochs.size()) {
                caster.send(epochs[next]);
                sent += epochs[next++];
            }
        };
        const Run r = cli({"ntrip", "--caster", casterArg(caster), "--mount", "MOUNT", "--user",
                           "rover7", "--password-env", "TEST_NTRIP_PW", "--ntrip-version", version,
                           "--gga", "55.75,37.62,150", "--out", file, "--duration", "1.5"},
                          feed);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(next >= 3);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray got = f.readAll();
        QVERIFY(got.size() > 0);
        QVERIFY(sent.startsWith(got)); // what arrived before the end, exactly
        const QList<QJsonObject> lines = jsonLines(r.out);
        QVERIFY(!lines.isEmpty());
        QCOMPARE(lines[0].value("type").toInt(), 1074);
        QCOMPARE(lines[1].value("type").toInt(), 1084);
        QCOMPARE(lines[2].value("type").toInt(), 1005);
        QVERIFY(r.err.contains("Receiving RTCM from 127.0.0.1:"));
        QVERIFY(r.err.contains("\"crc_failures\":0"));
        QVERIFY(caster.uploads.startsWith("$GPGGA,")); // the GGA went up
        QVERIFY(!r.err.contains("s3cret-pw") && !r.out.contains("s3cret-pw"));
    }

    void theNearestMountpointIsChosen() {
        TstCaster caster;
        QVERIFY(caster.listen());
        caster.user = "";
        int sent = 0;
        const QList<QByteArray> epochs = baseEpochs(20);
        auto feed = [&] {
            if (caster.streamingClients() == 1 && sent < epochs.size()) caster.send(epochs[sent++]);
        };
        // Near Saint Petersburg: FAR (RTCM 3.3) is nearest; OLD (RTCM 2.3) is not a candidate.
        caster.mountpoint = "FAR";
        caster.password = "";
        const Run r = cli({"ntrip", "--caster", casterArg(caster), "--nearest", "--gga",
                           "59.9,30.3,10", "--duration", "1", "--quiet"},
                          feed);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("nearest RTCM 3 mountpoint: FAR (Far base, 4.0 km)"),
                 r.err.constData());
        QVERIFY(r.out.isEmpty()); // --quiet
        QVERIFY(caster.requests.size() >= 2);
        QVERIFY(caster.requests.last().startsWith("GET /FAR HTTP/1.1"));
    }

    void refusalsEndWithTheReason_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("password");
        QTest::addColumn<QString>("words");
        QTest::addColumn<int>("status");
        QTest::newRow("wrong password")
                << QStringList{"--mount", "MOUNT",          "--user",
                               "rover7",  "--password-env", "TEST_NTRIP_PW"}
                << "wrong-one"
                << "refused the user name or password for mountpoint MOUNT" << 1;
        // A mountpoint the caster does not have is the request's fault (docs/cli.md).
        QTest::newRow("unknown mountpoint") << QStringList{"--mount", "NOSUCH"} << "x"
                                            << "Mountpoint NOSUCH is not on 127.0.0.1:" << 2;
    }
    void refusalsEndWithTheReason() {
        QFETCH(QStringList, args);
        QFETCH(QString, password);
        QFETCH(QString, words);
        QFETCH(int, status);
        TstCaster caster;
        QVERIFY(caster.listen());
        const Run r = cli(QStringList{"ntrip", "--caster", casterArg(caster)} + args, {}, password);
        QCOMPARE(r.exitCode, status);
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
        QVERIFY(!r.err.contains(password.toUtf8()));
    }

    void aRefusedPortIsRetriedUntilTheDurationEnds() {
        const Run r = cli({"ntrip", "--caster", QString("127.0.0.1:%1").arg(closedPort()),
                           "--mount", "M", "--duration", "1"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("nothing is listening on that port; trying again in 2 s"),
                 r.err.constData());
        QVERIFY2(r.err.contains("no RTCM received from 127.0.0.1:"), r.err.constData());
    }

    // The whole path: caster → gnss-cli → the simulated NV08C-RTK on a pseudo-terminal, which
    // is autonomous until the corrections flow, then float, then fixed; its fix goes up as GGA.
    void theRoverReachesRtkFixedOnlyOnceCorrectionsFlow() {
        gnss::link::test::SimProcess rover(
                {"--dialect", "nvs", "--speed", "5", "--baud", "460800"});
        if (!rover.ok()) QSKIP("gnss-sim is not built");
        TstCaster caster;
        QVERIFY(caster.listen());
        const QList<QByteArray> epochs = baseEpochs(200);
        int next = 0;
        QElapsedTimer clock;
        auto feed = [&] { // one base epoch per real second once the client streams
            if (caster.streamingClients() == 1 && next < epochs.size() &&
                (!clock.isValid() || clock.elapsed() >= 1000)) {
                clock.start();
                caster.send(epochs[next++]);
            }
        };
        const Run r = cli({"ntrip", "--caster", casterArg(caster), "--mount", "MOUNT", "--user",
                           "rover7", "--password-env", "TEST_NTRIP_PW", "--port", rover.device,
                           "--baud", "460800", "--duration", "12"},
                          feed);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QStringList fixes;
        for (const QJsonObject &e : jsonLines(r.out)) fixes.append(e.value("fix").toString());
        QVERIFY2(fixes.size() > 50, r.err.constData());
        // Autonomous (3d) first: the simulated rover does not correct itself.
        QVERIFY(fixes.contains("3d") && fixes.contains("rtk_float"));
        QVERIFY(fixes.indexOf("3d") < fixes.indexOf("rtk_float"));
        QCOMPARE(fixes.last(), QString("rtk_fixed"));
        QVERIFY2(r.err.contains("\"frames_dropped\":0"), r.err.constData());
        QVERIFY2(!r.err.contains("\"frames_forwarded\":0"), r.err.constData());
        // --gga auto: the receiver's own fix went up to the caster.
        QVERIFY(caster.uploads.contains("$GPGGA,"));
    }

    void badCommandLinesAreRefusedBeforeConnecting_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("words");
        QTest::newRow("no caster") << QStringList{"--mount", "M"} << "needs --caster HOST:PORT";
        QTest::newRow("two modes")
                << QStringList{"--caster", "h:1", "--mount", "M", "--sourcetable"}
                << "give one of --mount M, --sourcetable or --nearest";
        QTest::newRow("nearest without a position")
                << QStringList{"--caster", "h:1", "--nearest"} << "--nearest needs the rover";
        QTest::newRow("a bad position")
                << QStringList{"--caster", "h:1", "--mount", "M", "--gga", "95,1,1"}
                << "--gga expects auto or LAT,LON,H";
        QTest::newRow("a missing password variable")
                << QStringList{"--caster", "h:1", "--mount", "M", "--password-env", "NO_SUCH_VAR_X"}
                << "environment variable NO_SUCH_VAR_X is not set";
        QTest::newRow("two receivers") << QStringList{"--caster", "h:1",          "--mount", "M",
                                                      "--port",   "/dev/ttyUSB0", "--sim",   "nvs"}
                                       << "give one source";
        QTest::newRow("version 3")
                << QStringList{"--caster", "h:1", "--mount", "M", "--ntrip-version", "3"}
                << "--ntrip-version is 1 or 2";
    }
    void badCommandLinesAreRefusedBeforeConnecting() {
        QFETCH(QStringList, args);
        QFETCH(QString, words);
        const Run r = cli(QStringList{"ntrip"} + args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TstNtripCli)
#include "tst_ntrip_cli.moc"
