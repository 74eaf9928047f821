// gnss-cli end to end: the real executable on files, its JSON, its exit codes.
#include "cli_run.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss::test;

namespace {

const QByteArray kLog =
        "$GPRMC,153556.00,A,5550.602948,N,03732.239612,E,000.00000,000.0,310518,,,R*4E\r\n"
        "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,0100*"
        "46\r\n"
        "$GPGSV,1,1,04,02,43,143,51,03,08,014,39,06,45,081,49,12,87,266,55,1*6E\r\n"
        "garbage\x01\x02\r\n"
        "$GPGGA,000008.00,,,,,0,,,,,,,,,*40\r\n";

} // namespace

class TstCli : public QObject {
    Q_OBJECT
private slots:
    void decodePrintsOneJsonObjectPerSentence() {
        const Run r = runCli({"decode", "-"}, kLog);
        QCOMPARE(r.status, QProcess::NormalExit);
        QCOMPARE(r.exitCode, 0);
        const auto lines = jsonLines(r.out);
        QCOMPARE(lines.size(), 4);
        for (const auto &o : lines)
            for (const char *k : {"line", "address", "talker", "type", "checksum"})
                QVERIFY(o.contains(k));
        QCOMPARE(lines[1]["type"].toString(), QString("GGA"));
        QCOMPARE(lines[1]["data"].toObject()["quality"].toInt(), 4);
        QCOMPARE(lines[3]["checksum"].toString(), QString("bad"));
        QVERIFY(lines[3].contains("error"));
        QVERIFY(!lines[3].contains("data"));
    }

    void lenientDecodesBadChecksumsAndMarksThem() {
        const auto lines = jsonLines(runCli({"decode", "--lenient", "-"}, kLog).out);
        QCOMPARE(lines[3]["checksum"].toString(), QString("bad"));
        QCOMPARE(lines[3]["data"].toObject()["quality"].toInt(), 0);
    }

    void epochsPrintsOneSnapshotPerFix() {
        const auto lines = jsonLines(runCli({"epochs", "-"}, kLog).out);
        QCOMPARE(lines.size(), 1); // the no-fix GGA has a bad checksum
        QCOMPARE(jsonLines(runCli({"epochs", "--lenient", "-"}, kLog).out).size(), 2);
        QCOMPARE(lines[0]["time"].toString(), QString("2018-05-31T15:35:56.000Z"));
        QCOMPARE(lines[0]["fix"].toString(), QString("rtk_fixed"));
        QCOMPARE(lines[0]["sats_used"].toInt(), 15);
        QCOMPARE(lines[0]["satellites"].toArray().size(), 4);
        QVERIFY(lines[0]["satellites"].toArray()[0].toObject().contains("used"));
    }

    void statsCountsEverything() {
        QTemporaryDir dir;
        const QString path = dir.filePath("log.nmea");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kLog);
        f.close();
        const Run r = runCli({"stats", "--json", path});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["sentences"].toInt(), 4);
        QCOMPARE(o["checksum_bad"].toInt(), 1);
        QCOMPARE(o["bytes_skipped"].toInt(), 11);
        QCOMPARE(o["epochs"].toInt(), 1);
        QCOMPARE(o["addresses"].toArray().size(), 3);
        const Run text = runCli({"stats", path});
        QVERIFY(text.out.contains("GPGGA"));
        QVERIFY(text.out.contains("MB/s"));
    }

    void randomBytesNeverCrashAnyCommand() {
        QByteArray noise;
        auto *rng = QRandomGenerator::global();
        for (int i = 0; i < 200000; ++i) noise.append(char(rng->bounded(256)));
        noise += kLog;
        for (int i = 0; i < 2000; ++i) noise.append(i % 3 ? '$' : char(rng->bounded(256)));
        for (const char *cmd : {"decode", "epochs", "stats"}) {
            for (const char *lenient : {"--dialect=auto", "--lenient"}) {
                const Run r = runCli({cmd, lenient, "-"}, noise);
                QCOMPARE(r.status, QProcess::NormalExit);
                QCOMPARE(r.exitCode, 0);
            }
        }
    }

    void everyCaptureAndSpecExampleDecodesWithoutCrashing() {
        QStringList inputs;
        const QDir corpus(QStringLiteral(GNSS_SHARED_DIR "/corpus/gpsd"));
        for (const auto &l : corpus.entryList({"*.log"}, QDir::Files)) inputs << corpus.filePath(l);
        QFile examples(QStringLiteral(GNSS_SHARED_DIR "/specs/examples.tsv"));
        QTemporaryDir dir;
        if (examples.open(QIODevice::ReadOnly)) {
            // Every example as printed and, for typos, as corrected, one per line.
            QFile out(dir.filePath("examples.nmea"));
            QVERIFY(out.open(QIODevice::WriteOnly));
            examples.readLine();
            while (!examples.atEnd()) {
                const QList<QByteArray> cols = examples.readLine().trimmed().split('\t');
                for (int c : {1, 5})
                    if (cols.size() > c && !cols[c].isEmpty()) out.write(cols[c] + "\r\n");
            }
            out.close();
            inputs << out.fileName();
        }
        if (inputs.isEmpty()) QSKIP("../shared not present");
        for (const QString &in : inputs) {
            for (const char *cmd : {"decode", "epochs", "stats"}) {
                const Run r = runCli({cmd, "--lenient", in});
                QVERIFY2(r.status == QProcess::NormalExit && r.exitCode == 0,
                         qPrintable(QString("%1 %2: %3").arg(cmd, in, QString::fromUtf8(r.err))));
            }
        }
    }

    void renamedPrefixIsUsedOnOutputAndAcceptedOnInput() {
        Run r = runCli({"encode", "nemerix", "--prefix", "PXYZW", "--query", "rate.GGA"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.trimmed(), QByteArray("$PXYZW603*69"));
        const auto lines =
                jsonLines(runCli({"decode", "--dialect", "nemerix", "--prefix", "PXYZW", "-"},
                                 "$PXYZW600*xx\r\n")
                                  .out);
        QCOMPARE(lines.size(), 1);
        QVERIFY(lines[0].contains("data"));
        QCOMPARE(runCli({"encode", "nemerix", "--prefix", "pxyzw", "rate.GGA=1"}).exitCode, 2);
        QCOMPARE(runCli({"encode", "nvs", "--prefix", "PXYZW", "MODE=1"}).exitCode, 2);
    }

    void usageErrorsExitWithTwo() {
        QCOMPARE(runCli({"decode", "--dialect", "garmin", "-"}).exitCode, 2);
        QCOMPARE(runCli({"frobnicate"}).exitCode, 2);
        QCOMPARE(runCli({}).exitCode, 2);
        QCOMPARE(runCli({"decode", "/nonexistent/file"}).exitCode, 1);
    }
};

QTEST_GUILESS_MAIN(TstCli)
#include "tst_cli.moc"
