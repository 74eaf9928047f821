// gnss-cli export, summary and play end to end: the real executable on generated logs.
#include "bad_input_files.h"
#include "cli_run.h"
#include "raw_pty.h"
#include "scenario_log.h"

#include "builtin/simulators.h"
#include "sim/receiver.h"

#include <QDir>
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

class TstLogviewCli : public QObject {
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
        // A receiver that sends no vendor sentence is a standard NMEA one, not an unknown one.
        const QString plain = dir_.filePath("plain.nmea");
        QFile f(plain);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A\r\n"
                "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n");
        f.close();
        const Run plainRun = runCli({"summary", "--json", plain});
        QCOMPARE(QJsonDocument::fromJson(plainRun.out).object()["dialect"].toString(), "nmea");
        QVERIFY(runCli({"summary", plain}).out.contains("dialect: nmea (no vendor sentences)"));
        QCOMPARE(runCli({"summary", dir_.filePath("missing.nmea")}).exitCode, 1);
        QCOMPARE(runCli({"summary"}).exitCode, 2);
    }

    // --reference: a simulated NV08C-RTK told to report its position 0.3 m east, 0.2 m south
    // and 0.5 m up of the truth (--noise 0), against the simulator's observer: the bias comes
    // back, and the shares say every epoch is within 50 cm and none within 10 cm.
    void summaryAgainstAReference() {
        gnss::sim::SimOptions o;
        o.noise = 0;
        o.differences.east = 0.3;
        o.differences.north = -0.2;
        o.differences.up = 0.5;
        auto rx = gnss::sim::builtinSimulators().make("nvs", o);
        QVERIFY(rx);
        const QString path = dir_.filePath("offset.nmea");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            rx->advance(120);
            f.write(QByteArray::fromStdString(rx->takeOutput()));
        }
        const Run r = runCli({"summary", "--json", "--reference", "55.7512,37.6184,166.6", path});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject ref = QJsonDocument::fromJson(r.out).object()["reference"].toObject();
        QVERIFY2(ref["positions"].toInt() > 100, r.out.constData());
        const QJsonObject bias = ref["bias_m"].toObject();
        QVERIFY2(std::abs(bias["east"].toDouble() - 0.3) < 0.01, r.out.constData());
        QVERIFY2(std::abs(bias["north"].toDouble() + 0.2) < 0.01, r.out.constData());
        QVERIFY2(std::abs(bias["up"].toDouble() - 0.5) < 0.01, r.out.constData());
        QVERIFY(std::abs(ref["horizontal_m"].toObject()["r95"].toDouble() - 0.361) < 0.01);
        QVERIFY(std::abs(ref["vertical_m"].toObject()["p95"].toDouble() - 0.5) < 0.01);
        QCOMPARE(ref["within"].toObject()["0.1"].toDouble(), 0.0);
        QCOMPARE(ref["within"].toObject()["0.5"].toDouble(), 100.0);
        // Horizontal only without a height; the words say the same.
        const Run flat = runCli({"summary", "--json", "--reference", "55.7512,37.6184", path});
        const QJsonObject flatRef =
                QJsonDocument::fromJson(flat.out).object()["reference"].toObject();
        QVERIFY(!flatRef["bias_m"].toObject().contains("up"));
        QVERIFY(!flatRef.contains("vertical_m"));
        const Run text = runCli({"summary", "--reference", "55.7512,37.6184,166.6", path});
        QVERIFY2(text.out.contains("bias: east 0.300 m, north -0.200 m, up 0.500 m"),
                 text.out.constData());
        // A malformed point is refused before the log is read.
        const Run bad = runCli({"summary", "--reference", "55.7,north", path});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("longitude"), bad.err.constData());
    }

    // "-": standard input, read whole (through a temporary file, removed after), as a file is.
    void logCommandsReadStandardInput() {
        QFile f(log_);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        const Run fromFile = runCli({"summary", "--json", log_});
        const Run fromPipe = runCli({"summary", "--json", "-"}, bytes);
        QVERIFY2(fromPipe.exitCode == 0, fromPipe.err.constData());
        QJsonObject a = QJsonDocument::fromJson(fromFile.out).object();
        QJsonObject b = QJsonDocument::fromJson(fromPipe.out).object();
        QVERIFY(!b.isEmpty());
        a.remove("file");
        b.remove("file");
        QCOMPARE(b, a);
        const QString out = dir_.filePath("from-stdin.csv");
        const Run exported = runCli(
                {"export", "--format", "csv", "--from", "#10", "--to", "#19", "-", "-o", out},
                bytes);
        QVERIFY2(exported.exitCode == 0, exported.err.constData());
        QFile csv(out);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll().count('\n'), 11); // a header and ten epochs
        // An empty pipe is an empty log, said so; a bad request reads nothing first.
        const Run empty = runCli({"summary", "-"}, {});
        QCOMPARE(empty.exitCode, 0);
        QVERIFY2(empty.err.contains("standard input is empty"), empty.err.constData());
        QCOMPARE(runCli({"summary", "--from", "soon", "-"}, bytes).exitCode, 2);
        // No copy of standard input is left behind.
        QVERIFY(QDir(QDir::tempPath()).entryList({"gnss-cli-stdin-*"}).isEmpty());
    }

    // A time or epoch wholly outside the log is refused with the log's first and last epoch;
    // a range that only reaches past an end is cut to the log, and says so.
    void rangesOutsideTheLogAreRefusedOrCut_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("said");
        const QString span = "2024-03-15T10:00:00.000Z (#0) to 2024-03-15T09:10:29.000Z (#599)";
        QTest::newRow("summary from past the end")
                << QStringList{"summary", "--from", "#3000"} << 2
                << "--from #3000 is after the log's end: the log runs from " + span;
        QTest::newRow("summary to before the start")
                << QStringList{"summary", "--to", "2024-03-14T10:00:00Z"} << 2
                << "is before the log's start: the log runs from " + span;
        QTest::newRow("export from after to")
                << QStringList{"export", "--format", "csv", "--from", "#10", "--to", "#5"} << 2
                << "--from #10 is after --to #5: no epoch between them";
        QTest::newRow("export to past the end: cut")
                << QStringList{"export", "--format", "csv", "--from", "#590", "--to", "#3000"} << 0
                << "--to #3000 is after the log's end: to its last epoch, "
                   "2024-03-15T09:10:29.000Z (#599)";
        QTest::newRow("summary from before the start: cut")
                << QStringList{"summary", "--from", "2024-03-15T08:00:00Z", "--to", "#5"} << 0
                << "is before the log's start: from its first epoch, 2024-03-15T10:00:00.000Z (#0)";
    }
    void rangesOutsideTheLogAreRefusedOrCut() {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, said);
        const QString out = dir_.filePath("range.out");
        QFile::remove(out);
        QStringList all = args;
        all << log_;
        if (args.front() == "export") all << "-o" << out;
        const Run r = runCli(all);
        QCOMPARE(r.exitCode, code);
        QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
        if (code == 0 && args.front() == "export") {
            QFile f(out);
            QVERIFY(f.open(QIODevice::ReadOnly));
            QCOMPARE(f.readAll().count('\n'), 11); // a header and #590 to #599
        }
        if (code == 2 && args.front() == "export") QVERIFY(!QFile::exists(out));
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

    // A file that is no usable log: said so on standard error, and export writes no file.
    void aFileThatIsNotALogIsSaidSo_data() {
        QTest::addColumn<QStringList>("command");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QByteArray>("index"); // FILE.idx beside it, when not empty
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("words");
        QByteArray noise(20000, '\0');
        for (int i = 0; i < noise.size(); ++i) noise[i] = char((i * 7919 + 13) % 251);
        const QByteArray text("hello world\nthis is not NMEA\n");
        const QByteArray gga = kOneGga;
        const QStringList gpx{"export", "--format", "gpx"}, nmea{"export", "--format", "nmea"};
        QTest::newRow("export: binary noise")
                << gpx << noise << QByteArray() << 1 << "no NMEA found in";
        QTest::newRow("export: a text file")
                << nmea << text << QByteArray() << 1 << "nothing to export";
        QTest::newRow("export: an empty file")
                << gpx << QByteArray() << QByteArray() << 1 << "is empty";
        QTest::newRow("export: no such file")
                << gpx << QByteArray("-") << QByteArray() << 1 << "No such file";
        QTest::newRow("summary: a text file")
                << QStringList{"summary"} << text << QByteArray() << 0 << "no NMEA found in";
        QTest::newRow("play: a text file")
                << QStringList{"play", "--pty"} << text << QByteArray() << 1 << "nothing to play";
        // A recording's index that is someone else's file, or cut: the log is read without
        // its host times, and says so.
        QTest::newRow("summary: a foreign index")
                << QStringList{"summary"} << gga << QByteArray("<xml>\n") << 0
                << ".idx, line 1: not an index line (host times not used)";
        QTest::newRow("summary: an index past the data")
                << QStringList{"summary"} << gga << QByteArray("R 5000 0 9000\n") << 0
                << "line 1: chunk ends past the end of the data file";
    }
    void aFileThatIsNotALogIsSaidSo() {
        QFETCH(QStringList, command);
        QFETCH(QByteArray, bytes);
        QFETCH(QByteArray, index);
        QFETCH(int, code);
        QFETCH(QString, words);
        QTemporaryDir dir;
        const QString in = writeUserFile(dir, "input.log", bytes, index);
        const QString out = dir.filePath("out.gpx");
        QVERIFY(!in.isEmpty());
        QStringList args = command + QStringList{in};
        if (command.first() == "export") args << "-o" << out;
        const Run r = runCli(args, {}, 30000);
        QVERIFY2(r.exitCode == code, r.err.constData());
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
        QVERIFY(!QFile::exists(out));
    }

    void playNeedsOneOutput() {
        QCOMPARE(runCli({"play", log_}).exitCode, 2);
        QCOMPARE(runCli({"play", log_, "--pty", "--speed", "0"}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TstLogviewCli)
#include "tst_logview_cli.moc"
