// gnss-cli export, summary and play end to end: the real executable on generated logs.
#include "cli_run.h"
#include "raw_pty.h"
#include "scenario_log.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

using namespace gnss::test;

class TestLogviewCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString log_;
    QByteArray text_;

private slots:
    void initTestCase() {
        log_ = dir_.filePath("scenario.nmea");
        text_ = QByteArray::fromStdString(gnss::test::scenarioLog({}));
        QFile f(log_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text_);
    }

    void exportWritesEachFormat_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("contains");
        QTest::addColumn<int>("code");
        QTest::newRow("gpx") << QStringList{"--format", "gpx"} << "<trkpt" << 0;
        QTest::newRow("kml --out") << QStringList{"--format=kml"} << "<LineString>" << 0;
        QTest::newRow("csv range")
                << QStringList{"--format", "csv", "--from", "10:01:00", "--to", "10:01:09"}
                << "2024-03-15T10:01:09.000Z" << 0;
        QTest::newRow("nmea by epoch")
                << QStringList{"--format", "nmea", "--from", "#0", "--to", "#0"}
                << "$GPRMC,100000.00" << 0;
        QTest::newRow("bad format") << QStringList{"--format", "shp"} << "" << 2;
        QTest::newRow("bad time") << QStringList{"--format", "gpx", "--from", "noon"} << "" << 2;
    }
    void exportWritesEachFormat() {
        QFETCH(QStringList, args);
        QFETCH(QString, contains);
        QFETCH(int, code);
        const QString out = dir_.filePath("out.txt");
        QFile::remove(out);
        const Run r =
                runCli(QStringList{"export"} + args +
                       QStringList{log_, args.contains("--format=kml") ? "--out" : "-o", out});
        QCOMPARE(r.exitCode, code);
        if (code) return;
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray b = f.readAll();
        QVERIFY(b.contains(contains.toUtf8()));
        if (args.contains("csv")) QCOMPARE(b.count('\n'), 11);
        if (args.contains("nmea")) QCOMPARE(b, text_.left(b.size()));
    }

    void summaryJson() {
        const Run r = runCli({"summary", "--json", log_});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["stats"].toObject()["epochs"].toInt(), 600);
        QCOMPARE(o["stats"].toObject()["gaps"].toInt(), 1);
        QCOMPARE(o["stats"].toObject()["time_to_rtk_fixed_s"].toDouble(), 200.0);
        QVERIFY(o["stationary"].toObject()["position"].toObject()["cep95_m"].toDouble() > 0);
        QCOMPARE(o["events"].toArray().size(), 17);
        const Run text = runCli({"summary", log_});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("RTK fixed 28.3 %"));
        QVERIFY(text.out.contains("time_jump"));
        QCOMPARE(runCli({"summary", dir_.filePath("missing.nmea")}).exitCode, 1);
        QCOMPARE(runCli({"summary"}).exitCode, 2);
    }

    // play --pty: read back from the pseudo-terminal, byte for byte, at 200 times the pace.
    void playToAPseudoTerminal() {
        QProcess p;
        p.start(GNSS_CLI_PATH, {"play", log_, "--pty", "--speed", "200"});
        QVERIFY(p.waitForReadyRead(30000));
        const QByteArray path = p.readLine().trimmed();
        QVERIFY(path.startsWith("/dev/pts/"));
        const int fd = gnss::test::openRawPty(path.constData());
        QVERIFY(fd >= 0);
        QByteArray got;
        char buf[65536];
        QElapsedTimer timer;
        timer.start();
        while (got.size() < text_.size() && timer.elapsed() < 60000) {
            pollfd pf{fd, POLLIN, 0};
            if (::poll(&pf, 1, 200) <= 0) continue;
            const ssize_t n = ::read(fd, buf, sizeof buf);
            if (n <= 0) break;
            got.append(buf, n);
        }
        ::close(fd);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(got.size(), text_.size());
        QVERIFY(got == text_);
        // At 200 times a 630 s log: about 3 s, not instantly.
        QVERIFY(timer.elapsed() > 1500);
    }

    void playNeedsOneOutput() {
        QCOMPARE(runCli({"play", log_}).exitCode, 2);
        QCOMPARE(runCli({"play", log_, "--pty", "--speed", "0"}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestLogviewCli)
#include "tst_logview_cli.moc"
