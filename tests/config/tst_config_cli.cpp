// gnss-cli config end to end: against gnss-sim on a pseudo-terminal (get, set, export, diff,
// apply, a refused value), and against the in-process simulator (--sim).
#include "cli_run.h"
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

    void configOnTheInProcessSimulatorRefusesBadValuesBeforeSending() {
        Run r = cli({"--sim", "geostar", "set", "nav.ELEV=99"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("nav.ELEV"), why(r));
        QVERIFY2(!r.out.contains("\"sentence\""), why(r));
        r = cli({"--sim", "geostar", "set", "nav.ELEV=9"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("$GPSGG,ELEV09*7B"), why(r));
        r = cli({"--sim", "nemerix", "frobnicate"});
        QCOMPARE(r.exitCode, 2);
        r = cli({"--sim", "nvs", "action", "save"});
        QVERIFY2(r.exitCode == 0 && r.out.contains("$PNVGCFG,W*"), why(r));
        r = cli({"--sim", "nemerix", "action", "save"}); // the VT002 cannot save
        QCOMPARE(r.exitCode, 1);
    }
};

QTEST_GUILESS_MAIN(TstConfigCli)
#include "tst_config_cli.moc"
