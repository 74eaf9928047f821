// gnss-cli sites end to end, in a data folder of its own (GNSS_WORKBENCH_DATA_DIR): add, list,
// export, import, remove with their exit statuses; and summary --reference-site giving the same
// "reference" object as --reference at the site's antenna reference point.
#include "cli_run.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using gnss::test::Run;

namespace {

// A minute of GGA at one place (ellipsoidal height 150 + 14 m), a little noise in it.
QByteArray ggaLog() {
    QByteArray log;
    for (int s = 0; s < 60; ++s) {
        const QByteArray body =
                QStringLiteral(
                        "GPGGA,1000%1.00,5545.07%2,N,03737.10%3,E,1,08,0.9,150.%4,M,14.0,M,,")
                        .arg(s, 2, 10, QChar('0'))
                        .arg(20 + s % 7, 2, 10, QChar('0'))
                        .arg(40 + s % 5, 2, 10, QChar('0'))
                        .arg(s % 9)
                        .toLatin1();
        quint8 sum = 0;
        for (const char c : body) sum ^= static_cast<quint8>(c);
        log += '$' + body + '*' + QByteArray::number(sum, 16).toUpper().rightJustified(2, '0') +
               "\r\n";
    }
    return log;
}

} // namespace

class TstSitesCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QProcessEnvironment env_ = QProcessEnvironment::systemEnvironment();

    Run cli(const QStringList &args) {
        return gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH), args, {}, 60000, env_,
                                      dir_.path());
    }
    QString file(const QString &name) const { return dir_.filePath(name); }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        env_.insert("GNSS_WORKBENCH_DATA_DIR", dir_.filePath("data"));
        QFile log(file("still.nmea"));
        QVERIFY(log.open(QIODevice::WriteOnly));
        log.write(ggaLog());
    }

    void init() { QDir(dir_.filePath("data")).removeRecursively(); }

    void statuses_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("said");
        QTest::newRow("no action") << QStringList{"sites"} << 2 << "expected list, add";
        QTest::newRow("unknown action") << QStringList{"sites", "show"} << 2 << "unknown action";
        QTest::newRow("add without position") << QStringList{"sites", "add", "A"} << 2 << "--llh";
        QTest::newRow("add both positions")
                << QStringList{"sites", "add", "A", "--llh", "1,2", "--ecef", "1,2,3"} << 2
                << "one of them";
        QTest::newRow("bad llh") << QStringList{"sites", "add", "A", "--llh", "95,2"} << 2
                                 << "latitude";
        QTest::newRow("bad ecef") << QStringList{"sites", "add", "A", "--ecef", "1,2"} << 2
                                  << "--ecef";
        QTest::newRow("long name") << QStringList{"sites", "add", QString(65, 'n'), "--llh", "1,2"}
                                   << 2 << "at most 64";
        QTest::newRow("bad date") << QStringList{"sites", "add",    "A",        "--llh",
                                                 "1,2",   "--date", "yesterday"}
                                  << 2 << "date:";
        QTest::newRow("option of another action")
                << QStringList{"sites", "list", "--replace"} << 2 << "not an option of sites list";
        QTest::newRow("remove unknown")
                << QStringList{"sites", "remove", "Nowhere"} << 2 << "no site";
        QTest::newRow("export txt") << QStringList{"sites", "export", "a.txt"} << 2 << "FILE.csv";
        QTest::newRow("import missing")
                << QStringList{"sites", "import", "none.csv"} << 1 << "cannot read";
        QTest::newRow("list empty") << QStringList{"sites", "list"} << 0 << "";
    }
    void statuses() {
        QFETCH(QStringList, args);
        QFETCH(int, status);
        QFETCH(QString, said);
        const Run r = cli(args);
        QCOMPARE(r.exitCode, status);
        QVERIFY2(QString::fromUtf8(r.err).contains(said), r.err.constData());
        if (status == 2) QVERIFY(!QFile::exists(file("data/sites.json")));
    }

    void addListExportImportRemove() {
        Run r = cli({"sites", "add", "Крыша НИИ", "--llh", "55.7512,37.6184,166.6",
                     "--antenna-height", "1.5", "--accuracy", "0.02", "--note",
                     "a, \"quoted\" note", "--date", "2024-03-15"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        r = cli({"sites", "add", "Mast", "--ecef", "2846000,2197000,5250000", "--method", "ppp"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        r = cli({"sites", "add", "MAST", "--llh", "1,2"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("already in the list"));

        r = cli({"sites", "list"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("Крыша НИИ"));
        QVERIFY(r.out.contains("Mast"));
        r = cli({"sites", "list", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray sites = QJsonDocument::fromJson(r.out).object().value("sites").toArray();
        QCOMPARE(sites.size(), 2);
        QCOMPARE(sites[1].toObject().value("note").toString(), QString("a, \"quoted\" note"));
        QCOMPARE(sites[1].toObject().value("antenna_height").toDouble(), 1.5);
        QCOMPARE(sites[0].toObject().value("method").toString(), QString("ppp"));

        for (const QString &name : {QString("out.csv"), QString("out.json")}) {
            r = cli({"sites", "export", name});
            QVERIFY2(r.exitCode == 0, r.err.constData());
        }
        QFile csv(file("out.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QVERIFY(csv.readAll().contains("\"a, \"\"quoted\"\" note\""));

        r = cli({"sites", "remove", "Крыша НИИ"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        // Mast is there: a conflict, kept; the other comes back.
        r = cli({"sites", "import", "out.csv"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("'Mast'") && r.err.contains("imported 1 new"), r.err.constData());
        r = cli({"sites", "import", "out.json", "--replace"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.err.contains("replaced 2"));
        r = cli({"sites", "list", "--json"});
        QCOMPARE(QJsonDocument::fromJson(r.out).object().value("sites").toArray(), sites);

        QFile bad(file("bad.csv"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("name,lat,lon\nA,1,2\nB,1;5,2\n");
        bad.close();
        r = cli({"sites", "import", "bad.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("bad.csv: line 3: lat"), r.err.constData());
    }

    void referenceSite_data() {
        QTest::addColumn<QString>("site");      // the --llh given
        QTest::addColumn<QString>("antenna");   // --antenna-height
        QTest::addColumn<QString>("reference"); // the --reference it stands for
        QTest::newRow("with height") << "55.751200,37.618400,160.25"
                                     << "3.75"
                                     << "55.751200,37.618400,164";
        QTest::newRow("no height") << "55.751200,37.618400"
                                   << "1.5"
                                   << "55.751200,37.618400";
    }
    void referenceSite() {
        QFETCH(QString, site);
        QFETCH(QString, antenna);
        QFETCH(QString, reference);
        Run r = cli({"sites", "add", "Roof A", "--llh", site, "--antenna-height", antenna});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(cli({"sites", "add", "Roof B", "--llh", "1,2"}).exitCode == 0);
        const Run bySite = cli({"summary", "--json", "--reference-site", "roof a", "still.nmea"});
        QVERIFY2(bySite.exitCode == 0, bySite.err.constData());
        const Run byPoint = cli({"summary", "--json", "--reference", reference, "still.nmea"});
        QVERIFY2(byPoint.exitCode == 0, byPoint.err.constData());
        const QJsonObject a =
                QJsonDocument::fromJson(bySite.out).object().value("reference").toObject();
        const QJsonObject b =
                QJsonDocument::fromJson(byPoint.out).object().value("reference").toObject();
        QVERIFY(a.value("positions").toInt() > 50);
        QCOMPARE(a, b);
        QCOMPARE(a.contains("vertical_m"), site.count(',') == 2);
    }

    void referenceSiteRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        QTest::newRow("ambiguous")
                << QStringList{"summary", "--reference-site", "roof", "still.nmea"}
                << "'roof' is ambiguous: it begins 'Roof A' and 'Roof B'";
        QTest::newRow("unknown") << QStringList{"summary", "--reference-site", "Roof C",
                                                "still.nmea"}
                                 << "no site 'Roof C' (close: 'Roof A'";
        QTest::newRow("both") << QStringList{"summary",          "--reference", "1,2",
                                             "--reference-site", "Roof A",      "still.nmea"}
                              << "give one of them";
        QTest::newRow("ttff unknown")
                << QStringList{"ttff",   "--sim", "nvs", "--start", "cold", "--reference-site",
                               "Nowhere"}
                << "no site 'Nowhere'";
        QTest::newRow("ttff both") << QStringList{"ttff",  "--sim",       "nvs", "--start",
                                                  "cold",  "--reference", "1,2", "--reference-site",
                                                  "Roof A"}
                                   << "give one of them";
    }
    void referenceSiteRefused() {
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        QVERIFY(cli({"sites", "add", "Roof A", "--llh", "1,2"}).exitCode == 0);
        QVERIFY(cli({"sites", "add", "Roof B", "--llh", "1,2"}).exitCode == 0);
        const Run r = cli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(said), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TstSitesCli)
#include "tst_sites_cli.moc"
