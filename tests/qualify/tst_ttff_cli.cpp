// gnss-cli ttff end to end: gnss-sim on a pseudo-terminal told its restart times (--ttff) and run
// 20 times faster (--speed 20: a host second is 20 simulated ones), measured by the real
// QSerialPort link. The medians come back within 10 % of what the simulator was told (plus the
// host's latency, on a loaded machine); a start the receiver lacks is refused before anything is
// sent; a receiver that never fixes gives timeouts and the campaign still ends.
#include "cli_run.h"
#include "sim_process.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <map>

using gnss::link::test::SimProcess;
using gnss::test::Run;

namespace {

constexpr double kSpeed = 20;
// A busy host (two sanitizer builds on two cores) delivers the fix's sentences late, never
// early: measured times may run this much host time over what the simulator was told.
constexpr double kHostLatency = 0.25; // seconds

// Whether a time measured on the host (seconds) is what the simulator was told (simulated
// seconds): within 10 % below, and 10 % plus the host's latency above.
bool asTold(double hostSeconds, double told) {
    const double simulated = hostSeconds * kSpeed;
    return simulated >= 0.9 * told && simulated <= 1.1 * told + kHostLatency * kSpeed;
}

QByteArray why(const Run &r) {
    return "exit " + QByteArray::number(r.exitCode) + "\nstdout: " + r.out.right(3000) +
           "\nstderr: " + r.err.right(3000);
}

} // namespace

class TstTtffCli : public QObject {
    Q_OBJECT
private slots:
    // Each family told its times (simulated seconds; the NV08C-RTK has no hot start), three
    // runs of each kind it has.
    void aCampaignMeasuresWhatTheSimulatorWasTold_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("receiver");
        QTest::addColumn<QStringList>("starts");
        QTest::newRow("VT002") << "nemerix"
                               << "Nemerix VT002" << QStringList{"cold", "hot"};
        QTest::newRow("GeoS-5") << "geostar"
                                << "GeoStar GeoS-5" << QStringList{"cold", "warm", "hot"};
        QTest::newRow("NV08C-RTK") << "nvs"
                                   << "NVS NV08C-RTK" << QStringList{"cold", "warm"};
    }
    void aCampaignMeasuresWhatTheSimulatorWasTold() {
        QFETCH(QString, dialect);
        QFETCH(QString, receiver);
        QFETCH(QStringList, starts);
        const std::map<QString, double> told = {{"cold", 40.0}, {"warm", 30.0}, {"hot", 20.0}};
        SimProcess sim({"--dialect", dialect, "--baud", "115200", "--speed", "20", "--ttff",
                        "cold=40,warm=30,hot=20"});
        REQUIRE_SIM(sim);
        QStringList args = {"ttff",   "--port",    sim.device, "--baud", "115200",
                            "--runs", "3",         "--pause",  "0.2",    "--hold",
                            "0.5",    "--timeout", "20",       "--json"};
        for (const QString &s : starts) args << "--start" << s;
        const Run r = gnss::test::runCli(args, {}, 120000);
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(!o.isEmpty(), why(r));
        for (const QString &kind : starts) {
            const QJsonObject s = o["starts"].toObject()[kind].toObject();
            QCOMPARE(s["runs"].toInt(), 3);
            QCOMPARE(s["fixed"].toInt(), 3);
            const double median = s["ttff_s"].toObject()["median"].toDouble() * kSpeed;
            const double expected = told.at(kind);
            QVERIFY2(asTold(median / kSpeed, expected),
                     qPrintable(QString("%1: %2 s simulated\n").arg(kind).arg(median) + why(r)));
        }
        QCOMPARE(o["runs"].toArray().size(), 3 * int(starts.size()));
        QCOMPARE(o["receiver"].toString(), receiver);
        // The words: a line per run, then the table.
        QVERIFY(r.err.contains((starts.front() + " 1 of 3").toUtf8()));
        // Where the whole campaign is after each run but the last.
        const int total = 3 * int(starts.size());
        QVERIFY2(r.err.contains(QString("run 1 of %1 after ").arg(total).toUtf8()) &&
                         r.err.contains("min left"),
                 why(r));
        QVERIFY(!r.err.contains(QString("run %1 of %1").arg(total).toUtf8()));
    }

    // The NV08C-RTK has no hot start: said, and nothing sent (the simulator would have
    // restarted; its fix is still there right after).
    void aStartTheReceiverLacksIsRefused() {
        const Run r = gnss::test::runCli({"ttff", "--sim", "nvs", "--start", "hot"}, {}, 60000);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("has no hot start") && r.err.contains("cold, warm"), why(r));
        QVERIFY(r.err.contains("nothing was sent"));
        QCOMPARE(gnss::test::runCli({"ttff", "--sim", "nvs"}).exitCode, 2);
        QCOMPARE(gnss::test::runCli({"ttff", "--sim", "nvs", "--start", "tepid"}).exitCode, 2);
        QCOMPARE(gnss::test::runCli({"ttff", "--sim", "nvs", "--start", "cold", "--runs", "0"})
                         .exitCode,
                 2);
        // A limit or a report that cannot be: refused before the receiver is opened.
        const Run limit = gnss::test::runCli(
                {"ttff", "--sim", "nvs", "--start", "cold", "--limit", "cold:avg<=60"});
        QCOMPARE(limit.exitCode, 2);
        QVERIFY2(limit.err.contains("mean, median, p90, p95 or max"), why(limit));
        const Run report = gnss::test::runCli(
                {"ttff", "--sim", "nvs", "--start", "cold", "--report", "campaign.txt"});
        QCOMPARE(report.exitCode, 2);
        QVERIFY2(report.err.contains(".pdf or .html"), why(report));
    }

    // Limits held and reported (one met, one not: exit 1), and the report to hand over with its
    // CSV and JSON beside it, made without a display; pdftotext reads the identity and the
    // table back.
    void limitsAndTheReport() {
        SimProcess sim({"--dialect", "nemerix", "--baud", "115200", "--speed", "20", "--ttff",
                        "cold=40:4"});
        REQUIRE_SIM(sim);
        QTemporaryDir dir;
        const QString pdf = dir.filePath("vt002.pdf");
        const Run r = gnss::test::runCli({"ttff",
                                          "--port",
                                          sim.device,
                                          "--baud",
                                          "115200",
                                          "--start",
                                          "cold",
                                          "--runs",
                                          "2",
                                          "--pause",
                                          "0.2",
                                          "--timeout",
                                          "20",
                                          "--limit",
                                          "cold:mean<=60",
                                          "--limit",
                                          "cold:max<=0.5",
                                          "--reference",
                                          "55.7512,37.6184,167.1",
                                          "--report",
                                          pdf,
                                          "--json"},
                                         {}, 120000);
        QVERIFY2(r.exitCode == 1, why(r)); // a limit not met
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        const QJsonArray limits = o["limits"].toArray();
        QCOMPARE(limits.size(), 2);
        QCOMPARE(limits[0].toObject()["pass"].toBool(), true);
        QCOMPARE(limits[1].toObject()["pass"].toBool(), false);
        QVERIFY(limits[1].toObject()["value_s"].toDouble() > 0.5);
        QVERIFY2(o["reference"].toObject()["positions"].toInt() > 0, why(r));
        for (const char *f : {"vt002.pdf", "vt002.csv", "vt002.json"})
            QVERIFY2(QFile::exists(dir.filePath(f)), f);
        QFile csv(dir.filePath("vt002.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll().count('\n'), 3); // the header and a row per run
        const QString pdftotext = QStandardPaths::findExecutable("pdftotext");
        if (pdftotext.isEmpty()) QSKIP("pdftotext (poppler-utils) is not installed");
        QProcess p;
        p.start(pdftotext, {"-layout", pdf, "-"});
        QVERIFY(p.waitForFinished(20000));
        const QString text = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(text.contains("VT002") && text.contains(sim.device), qPrintable(text.left(1500)));
        QVERIFY(text.contains("Median") && text.contains("cold"));
        QVERIFY(text.contains("Limits"));
    }

    // The report in the language and units asked for (the window's translations, compiled into
    // gnss-cli); a language or unit it has not is refused before anything is sent.
    void theReportInRussianAndFeet() {
        for (const QStringList &bad : {QStringList{"--lang", "de"}, {"--units", "furlongs"}}) {
            const Run r = gnss::test::runCli(
                    QStringList{"ttff", "--sim", "nvs", "--start", "cold", "--report", "r.html"} +
                    bad);
            QVERIFY2(r.exitCode == 2 && r.err.contains(bad[0].toUtf8() + " expects"), why(r));
        }
        SimProcess sim({"--dialect", "nemerix", "--baud", "115200", "--speed", "20", "--ttff",
                        "cold=40:4"});
        REQUIRE_SIM(sim);
        QTemporaryDir dir;
        const QString html = dir.filePath("vt002.html");
        const Run r = gnss::test::runCli(
                {"ttff",     "--port",  sim.device, "--baud",      "115200",
                 "--start",  "cold",    "--runs",   "1",           "--timeout",
                 "20",       "--pause", "0.5",      "--reference", "55.7512,37.6184,167.1",
                 "--report", html,      "--lang",   "ru",          "--units",
                 "imperial"},
                {}, 120000);
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.out.contains("cold 1: fixed"), why(r)); // standard output stays English
        QFile f(html);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains(QStringLiteral("Отчёт о квалификации приёмника")),
                 qPrintable(text.left(600)));
        QVERIFY(text.contains(QStringLiteral("Медиана")));
        QVERIFY(text.contains(QStringLiteral("\u00a0фт")));
        QVERIFY(!text.contains(QStringLiteral("Median")));
    }

    // Unplugged in the middle of the first run (the line drops 100 simulated seconds after the
    // campaign's program took it, for 20 s, and comes back at the same name): that run is lost,
    // the campaign waits for the receiver and the second run fixes.
    void anUnplugMidRunIsSurvived() {
        QTemporaryDir dir;
        const QString link = dir.filePath("vt002");
        SimProcess sim({"--dialect", "nemerix", "--baud", "115200", "--speed", "20", "--ttff",
                        "cold=200", "--faults", "hangup=100/20x1", "--link", link});
        REQUIRE_SIM(sim);
        const Run r =
                gnss::test::runCli({"ttff", "--port", link, "--baud", "115200", "--start", "cold",
                                    "--runs", "2", "--pause", "0.2", "--timeout", "30", "--json"},
                                   {}, 120000);
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonArray runs = QJsonDocument::fromJson(r.out).object()["runs"].toArray();
        QCOMPARE(runs.size(), 2);
        QCOMPARE(runs[0].toObject()["outcome"].toString(), QString("lost"));
        QCOMPARE(runs[1].toObject()["outcome"].toString(), QString("fixed"));
        QVERIFY2(asTold(runs[1].toObject()["ttff_s"].toDouble(), 200), why(r));
        QVERIFY2(r.err.contains("link lost"), why(r));
    }

    // Never a fix (a cold start of ten simulated minutes, a one-second timeout): both runs time
    // out, and the campaign ends with its table.
    void aReceiverThatNeverFixesTimesOut() {
        SimProcess sim({"--dialect", "geostar", "--baud", "115200", "--ttff", "cold=600"});
        REQUIRE_SIM(sim);
        const Run r =
                gnss::test::runCli({"ttff", "--port", sim.device, "--baud", "115200", "--start",
                                    "cold", "--runs", "2", "--timeout", "1", "--pause", "0.1"},
                                   {}, 60000);
        QVERIFY2(r.exitCode == 0, why(r));
        QCOMPARE(r.out.count("cold 1: timeout") + r.out.count("cold 2: timeout"), 2);
        QVERIFY2(r.out.contains("cold      2     0        2"), why(r));
    }

    // A warm start needs a fix held first: a receiver that gives none (its power-on fix never
    // comes) times each run out at the limit, its restart not sent, and the campaign ends.
    void aWarmStartWithNoFixToHoldTimesOut() {
        SimProcess sim({"--dialect", "geostar", "--baud", "115200", "--ttff", "power=600"});
        REQUIRE_SIM(sim);
        const Run r = gnss::test::runCli({"ttff", "--port", sim.device, "--baud", "115200",
                                          "--start", "warm", "--runs", "2", "--timeout", "1",
                                          "--hold", "0.5", "--pause", "0.1"},
                                         {}, 60000);
        QVERIFY2(r.exitCode == 0, why(r));
        QCOMPARE(r.out.count("warm 1: timeout") + r.out.count("warm 2: timeout"), 2);
        QVERIFY2(r.out.contains("warm      2     0        2"), why(r));
    }
};

QTEST_GUILESS_MAIN(TstTtffCli)
#include "tst_ttff_cli.moc"
