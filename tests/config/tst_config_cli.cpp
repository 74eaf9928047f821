// gnss-cli config end to end: against gnss-sim on a pseudo-terminal (get, set, export, diff,
// apply, a refused value), against the in-process simulator (--sim), and bad input (profiles
// that cannot be applied, sources that cannot be opened) refused with nothing sent.
#include "bad_input_files.h"
#include "cli_run.h"
#include "listening_pty.h"
#include "sim_process.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using gnss::link::test::SimProcess;

namespace {

using gnss::test::Run;

Run cli(const QStringList &args) {
    return gnss::test::runCli(QStringList{"config"} + args, {}, 60000);
}

QByteArray why(const Run &r) {
    return "rc " + QByteArray::number(r.exitCode) + "\n" + r.out + "\n" + r.err;
}

QByteArray nvsProfile(const QByteArray &values, const QByteArray &model = "NV08C-RTK-A") {
    return "{\"format\":\"gnss-workbench-settings\",\"version\":1,\"dialect\":\"nvs\","
           "\"model\":\"" +
           model + "\",\"values\":{" + values + "}}";
}

} // namespace

class TstConfigCli : public QObject {
    Q_OBJECT
private slots:
    void configRoundTripsAProfileThroughGnssSimOnAPty() {
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimProcess sim({"--dialect", "nvs"});
        if (!sim.ok()) QSKIP(qPrintable("no pseudo-terminal: " + sim.error));
        const QStringList port{"--port", sim.device, "--baud", "115200", "--dialect", "nvs"};

        Run r = cli(port + QStringList{"get", "rtk.MODE", "port.COM1.baud"});
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject got = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(got["dialect"].toString(), QString("nvs"));
        QCOMPARE(got["values"].toObject()["rtk.MODE"].toString(), QString("2"));
        QVERIFY(got["values"].toObject()["port.COM1.baud"].isNull());
        QCOMPARE(got["write_only"].toArray().size(), 1);

        r = cli(port + QStringList{"set", "rtk.ELGPS=12", "pps.duration=250"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("\"verdict\":\"verified\""), why(r));
        QVERIFY2(r.out.contains("\"outcome\":\"accepted\""), why(r));

        QTemporaryDir dir;
        const QString file = dir.filePath("rover.json");
        r = cli(port + QStringList{"export", file});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY(QFile::exists(file));

        r = cli(port + QStringList{"set", "rtk.ELGPS=20"});
        QVERIFY2(r.exitCode == 0, why(r));
        r = cli(port + QStringList{"diff", file});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("\"key\":\"rtk.ELGPS\",\"profile\":\"12\",\"receiver\":\"20\""),
                 why(r));

        r = cli(port + QStringList{"apply", file});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("\"ok\":true"), why(r));
        r = cli(port + QStringList{"diff", file});
        QVERIFY2(r.exitCode == 0 && r.out.trimmed().isEmpty(), why(r));

        // A speed the receiver does not have: it answers with the one in force.
        r = cli(port + QStringList{"set", "port.COM2.baud=5000", "port.COM2.protocol=1"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("\"outcome\":\"refused\""), why(r));
        QVERIFY2(r.out.contains("\"verdict\":\"not taken\""), why(r));

        // Speed and dialect found by themselves.
        r = cli({"--port", sim.device, "get", "rtk.PVTRATE"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("\"rtk.PVTRATE\":\"5\""), why(r));
    }

    // A profile that cannot be applied is refused before the port is written to at all (not
    // even a query): the port is a pseudo-terminal the test reads.
    void aBadProfileIsRefusedBeforeAnythingIsSent_data() {
        QTest::addColumn<QString>("action");
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("words");
        const QByteArray geostar = R"({"format":"gnss-workbench-settings","version":1,)"
                                   R"("dialect":"geostar","values":{"nav.ELEV":"5"}})";
        for (const QString action : {"apply", "diff"}) {
            auto row = [&](const char *name) -> QTestData & {
                return QTest::addRow("%s: %s", qPrintable(action), name) << action;
            };
            row("not JSON") << QByteArray("rtk.ELGPS=12\n") << "not a settings profile";
            row("cut short") << nvsProfile(R"("rtk.ELGPS":"12")").left(50)
                             << "not a settings profile";
            row("a newer version") << nvsProfile({}).replace(R"("version":1)", R"("version":9)")
                                   << "profile version 9 is not supported";
            row("another dialect")
                    << geostar << "the profile is for dialect 'geostar', the receiver speaks 'nvs'";
            row("an unknown key") << nvsProfile(R"("rtk.ELGPS":"12","rtk.WARP":"9")")
                                  << "cannot set: rtk.WARP";
        }
    }
    void aBadProfileIsRefusedBeforeAnythingIsSent() {
        QFETCH(QString, action);
        QFETCH(QByteArray, json);
        QFETCH(QString, words);
        gnss::test::ListeningPty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        QTemporaryDir dir;
        const QString file = gnss::test::writeUserFile(dir, "bad.json", json);
        QVERIFY(!file.isEmpty());
        const Run r =
                cli({"--port", pty.device(), "--baud", "115200", "--dialect", "nvs", action, file});
        QVERIFY2(r.exitCode == 2, why(r)); // a usage error: the profile is not for this receiver
        QVERIFY2(r.err.contains(words.toUtf8()), why(r));
        QVERIFY2(r.out.isEmpty(), why(r));
        QCOMPARE(pty.written(), QByteArray());
    }

    // A profile of another model, or with a value out of range: the receiver is read (which
    // tells its model and what differs), nothing is written to it, and its settings are as
    // they were.
    void aProfileThatDoesNotSuitTheReceiverChangesNothing_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("words");
        QTest::newRow("another model")
                << nvsProfile(R"("rtk.ELGPS":"33")", "NV08C-CSM") << 2
                << "the profile is for the NV08C-CSM, the receiver is a NV08C-RTK-A";
        QTest::newRow("a value out of range")
                << nvsProfile(R"("rtk.ELGPS":"33","rtk.ELGLO":"91")") << 2
                << "nothing was sent: rtk.ELGLO: 91 is out of range; accepted: 0..90";
    }
    void aProfileThatDoesNotSuitTheReceiverChangesNothing() {
        QFETCH(QByteArray, json);
        QFETCH(int, exitCode);
        QFETCH(QString, words);
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimProcess sim({"--dialect", "nvs"});
        if (!sim.ok()) QSKIP(qPrintable("no pseudo-terminal: " + sim.error));
        const QStringList port{"--port", sim.device, "--baud", "115200", "--dialect", "nvs"};
        QTemporaryDir dir;
        const QString file = gnss::test::writeUserFile(dir, "profile.json", json);
        QVERIFY(!file.isEmpty());
        Run r = cli(port + QStringList{"apply", file});
        QVERIFY2(r.exitCode == exitCode, why(r));
        QVERIFY2(r.err.contains(words.toUtf8()), why(r));
        QVERIFY2(!r.out.contains("\"sentence\""), why(r)); // no command went out
        r = cli(port + QStringList{"get", "rtk.ELGPS", "rtk.ELGLO"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(!r.out.contains("\"rtk.ELGPS\":\"33\""), why(r));
        QVERIFY2(!r.out.contains("\"rtk.ELGLO\":\"91\""), why(r));
    }

    // A source that cannot be opened: said so, and how it is spelled when it is malformed.
    void aSourceThatCannotBeOpenedIsSaidSo_data() {
        QTest::addColumn<QStringList>("source");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("words");
        QTest::newRow("a misspelled port")
                << QStringList{"--port", "/dev/ttyUSB-no-such"} << 1
                << "Cannot open /dev/ttyUSB-no-such: No such file or directory";
        QTest::newRow("a port name without /dev")
                << QStringList{"--port", "ttyNOSUCH9"} << 1 << "Cannot open ttyNOSUCH9";
        QTest::newRow("a closed TCP port") << QStringList{"--tcp", "127.0.0.1:1"} << 1
                                           << "Cannot connect to 127.0.0.1:1: Connection refused";
        QTest::newRow("TCP without a port")
                << QStringList{"--tcp", "127.0.0.1"} << 2 << "--tcp takes HOST:PORT";
        QTest::newRow("TCP port out of range")
                << QStringList{"--tcp", "localhost:70000"} << 2 << "--tcp takes HOST:PORT";
        QTest::newRow("a simulator of no dialect")
                << QStringList{"--sim", "garmin"} << 2 << "garmin";
        QTest::newRow("a speed that is none")
                << QStringList{"--port", "/dev/null", "--baud", "fast"} << 2
                << "--baud expects a speed";
    }
    void aSourceThatCannotBeOpenedIsSaidSo() {
        QFETCH(QStringList, source);
        QFETCH(int, exitCode);
        QFETCH(QString, words);
        const Run r = cli(source + QStringList{"get"});
        QVERIFY2(r.exitCode == exitCode, why(r));
        QVERIFY2(r.err.contains(words.toUtf8()), why(r));
        QVERIFY2(r.out.isEmpty(), why(r));
    }

    void configOnTheInProcessSimulatorRefusesBadValuesBeforeSending() {
        // Out of range: a wrong request (2), refused before sending and said so.
        Run r = cli({"--sim", "geostar", "set", "nav.ELEV=99"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("nav.ELEV"), why(r));
        QVERIFY2(!r.out.contains("\"sentence\""), why(r));
        QVERIFY2(r.out.contains(R"("verdict":"refused before sending")"), why(r));
        QVERIFY2(r.out.contains(R"("commands":0)"), why(r));
        r = cli({"--sim", "geostar", "set", "nav.ELEV=9"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("$GPSGG,ELEV09*7B"), why(r));
        r = cli({"--sim", "nemerix", "frobnicate"});
        QCOMPARE(r.exitCode, 2);
        r = cli({"--sim", "nvs", "action", "save"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("$PNVGCFG,W*"), why(r));
        // The VT002 cannot save: known before anything is sent, so the request is wrong (2).
        r = cli({"--sim", "nemerix", "action", "save"});
        QCOMPARE(r.exitCode, 2);
    }

    // A key as the spec writes it, in any case, is the schema's key: read, set and verified; an
    // unknown or ambiguous one is a wrong request (2), said with the keys it could mean.
    void keysInEveryFormPeopleWriteThem() {
        Run r = cli({"--sim", "nvs", "get", "ELGPS", "rtk.elglo"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("\"rtk.ELGPS\":\"") && r.out.contains("\"rtk.ELGLO\":\""), why(r));
        r = cli({"--sim", "nvs", "set", "pvtrate=2"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("\"key\":\"rtk.PVTRATE\"") && r.out.contains("verified"), why(r));
        r = cli({"--sim", "nvs", "get", "PVTRAT"});
        QVERIFY2(r.exitCode == 2 && r.err.contains("did you mean rtk.PVTRATE"), why(r));
        r = cli({"--sim", "nvs", "set", "NOSUCH=1"});
        QVERIFY2(r.exitCode == 2 && !r.out.contains("\"sentence\""), why(r));
        r = cli({"--sim", "nvs", "set", "baud=9600"});
        QVERIFY2(r.exitCode == 2 && r.err.contains("port.COM2.baud"), why(r));
        const Run encoded = gnss::test::runCli({"encode", "nvs", "Pvtrate=5"}, {}, 60000);
        QVERIFY2(encoded.exitCode == 0 && encoded.out.startsWith("$PNVGRTK,PVTRATE,5*"),
                 why(encoded));
        QCOMPARE(gnss::test::runCli({"encode", "nvs", "NOSUCH=1"}, {}, 60000).exitCode, 2);
    }

    // Each verdict says how it is known: a write-only setting is confirmed by its command's
    // answer, never "verified" (read back), and `get` lists it as write-only, as it is; a get of
    // some keys names the receiver as a get of all does.
    void verdictsSayHowTheValueIsKnown() {
        Run r = cli({"--sim", "nvs", "set", "port.COM1.baud=38400"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains(R"("key":"port.COM1.baud","set":"38400","reported":"38400",)"
                                R"x("verdict":"confirmed by its reply (write-only)")x"),
                 why(r));
        QVERIFY2(!r.out.contains(R"("key":"port.COM1.baud","set":"38400","reported":"38400",)"
                                 R"("verdict":"verified")"),
                 why(r));
        r = cli({"--sim", "nvs", "get", "port.COM1.baud", "PVTRATE"});
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject got = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(got["write_only"].toArray(), QJsonArray{"port.COM1.baud"});
        QVERIFY(!got["values"].toObject()["rtk.PVTRATE"].toString().isEmpty());
        QCOMPARE(got["model"].toString(), QString("NV08C-RTK-A"));
        QVERIFY(!got["firmware"].toString().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TstConfigCli)
#include "tst_config_cli.moc"
