// Nothing read from a receiver, a log or a profile is executed or used as a path. The product
// runs no program at all (no QProcess, system, popen or exec in app/, ui/, protocol/: audited)
// and writes only where the user pointed (a command-line argument, a file dialog) or beside it
// (FILE.idx of a recording). These hold it for the inputs that carry text: a settings profile
// and a log whose every text field is a path ("../../escaped"), a shell command ("$(touch
// MARKER)") or markup, applied, compared and exported: no file appears but the one asked for,
// no marker is made, the text is escaped where it goes into a file.
#include "builtin_registry.h"
#include "cli_run.h"
#include "core/sentence_builder.h"
#include "logview/log_events.h"
#include "logview/log_view.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cstdio>

using gnss::test::Run;

namespace {

// Hostile texts: paths out of the folder, absolute paths, shell commands, markup. MARKER is
// replaced by a path in the test's folder: a file there would mean something ran it.
const QStringList kHostile{
        QStringLiteral("../../escaped-MARKER"),    QStringLiteral("/tmp/escaped-MARKER"),
        QStringLiteral("$(touch MARKER)"),         QStringLiteral("`touch MARKER`; touch MARKER"),
        QStringLiteral("<a href=\"x\">&amp;</a>"),
};

QString hostile(int i, const QString &marker) {
    return QString(kHostile[i % kHostile.size()]).replace(QStringLiteral("MARKER"), marker);
}

// Every file under `dir` (relative paths, sorted).
QStringList filesIn(const QString &dir) {
    QStringList out;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    const QDir base(dir);
    while (it.hasNext()) out << base.relativeFilePath(it.next());
    out.sort();
    return out;
}

// Runs gnss-cli in `dir`.
Run cliIn(const QString &dir, const QStringList &args) {
    return gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH), args, {}, 120000,
                                  QProcessEnvironment::systemEnvironment(), dir);
}

QByteArray sentence(const QByteArray &body) {
    return QByteArray::fromStdString(gnss::buildSentence(body.toStdString())) + "\r\n";
}

} // namespace

class TstUntrustedInput : public QObject {
    Q_OBJECT
private slots:
    // A profile whose texts are paths and commands: read, compared and applied to the
    // simulated receiver; nothing is written, nothing runs.
    void aProfilesTextsAreNeverPathsOrCommands_data() {
        QTest::addColumn<QString>("command");
        QTest::newRow("diff") << "diff";
        QTest::newRow("apply") << "apply";
    }
    void aProfilesTextsAreNeverPathsOrCommands() {
        QFETCH(QString, command);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QDir(dir.path()).mkpath("work/inner");
        const QString work = dir.filePath("work/inner");
        const Run exported = cliIn(work, {"config", "--sim", "nvs", "export", "profile.json"});
        QVERIFY2(exported.exitCode == 0, exported.err.constData());
        QFile f(QDir(work).filePath("profile.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject p = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QVERIFY(p.contains("values"));
        const QString marker = dir.filePath("MARKER-made");
        p["firmware"] = hostile(0, marker);
        p["created"] = hostile(2, marker);
        // Every text value of the receiver's own becomes a hostile text (numbers stay: the
        // schema refuses anything else for them, and a refusal is fine too).
        QJsonObject values = p["values"].toObject();
        int i = 0;
        for (auto it = values.begin(); it != values.end(); ++it, ++i) {
            bool number = false;
            it.value().toString().toDouble(&number);
            if (!number) it.value() = hostile(i, marker);
        }
        p["values"] = values;
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(p).toJson());
        f.close();
        const QStringList before = filesIn(dir.path());

        const Run r = cliIn(work, {"config", "--sim", "nvs", command, "profile.json"});
        QVERIFY2(r.exitCode >= 0 && r.exitCode <= 2, r.err.constData()); // ran, did not crash
        QCOMPARE(filesIn(dir.path()), before);
        QVERIFY(!QFile::exists(marker));
        QVERIFY(!QFile::exists(QStringLiteral("/tmp/escaped-") + marker));
    }

    // A log whose sentences carry paths, commands and markup, under a file name with markup:
    // exported to what was asked, and nothing else; the name escaped in the XML.
    void aLogsTextsAreNeverPathsOrCommands_data() {
        QTest::addColumn<QString>("format");
        for (const char *f : {"gpx", "kml", "csv", "nmea"}) QTest::newRow(f) << f;
    }
    void aLogsTextsAreNeverPathsOrCommands() {
        QFETCH(QString, format);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QDir(dir.path()).mkpath("logs");
        const QString marker = dir.filePath("MARKER-made");
        const QString name = QStringLiteral("drive <b>&\"x\" $(touch %1)").arg(marker);
        const QString logPath = dir.filePath("logs/" + QString(name).replace('/', '_') + ".nmea");
        QByteArray log;
        for (int s = 0; s < 10; ++s) {
            const QByteArray t = "1042" + QByteArray::number(s).rightJustified(2, '0') + ".00";
            log += sentence("GPGGA," + t + ",5545.0720,N,03737.1040,E,1,08,0.9,152.0,M,14.0,M,,");
            log += sentence("GPRMC," + t + ",A,5545.0720,N,03737.1040,E,0.0,0.0,150324,,,A");
            log += sentence("GPTXT,01,01,02," + hostile(s, marker).toUtf8().replace(',', ' '));
        }
        QFile f(logPath);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(log);
        f.close();
        const QStringList before = filesIn(dir.path());

        const QString out = dir.filePath("out." + format);
        const Run r = cliIn(dir.path(), {"export", "--format", format, "-o", out, logPath});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QStringList expected = before;
        expected << QStringLiteral("out.") + format;
        expected.sort();
        QCOMPARE(filesIn(dir.path()), expected);
        QVERIFY(!QFile::exists(marker));
        if (format == "gpx" || format == "kml") {
            QFile o(out);
            QVERIFY(o.open(QIODevice::ReadOnly));
            QXmlStreamReader x(&o);
            QString shownName;
            while (!x.atEnd()) {
                x.readNext();
                if (x.isStartElement() && x.name() == QLatin1String("name") && shownName.isEmpty())
                    shownName = x.readElementText();
            }
            QVERIFY2(!x.hasError(), qPrintable(x.errorString()));
            // The log's name, as it is (gnss-cli keeps the suffix, the window drops it).
            QVERIFY2(shownName.startsWith(QFileInfo(logPath).completeBaseName()),
                     qPrintable(shownName));
        }
    }

    // A recording's index says why its link dropped, in words that end up in the events CSV:
    // a text a spreadsheet would run as a formula is written so it cannot be one.
    void aRecordingsGapTextIsNeverAFormula_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("=") << QByteArray("=HYPERLINK(\"http://example.invalid\",\"x\")");
        QTest::newRow("+") << QByteArray("+cmd|' /C calc'!A0");
        QTest::newRow("-") << QByteArray("-2+3+cmd|' /C calc'!A0");
        QTest::newRow("@") << QByteArray("@SUM(1+1)*cmd|' /C calc'!A0");
        QTest::newRow("a tab first") << QByteArray("\t=1+1");
        QTest::newRow("words") << QByteArray("link lost: /dev/ttyUSB0: No such device");
    }
    void aRecordingsGapTextIsNeverAFormula() {
        QFETCH(QByteArray, text);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("rec.nmea");
        QByteArray log, index = "# gnss-workbench recording index 1\n";
        qint64 ms = 1710496800000;
        for (int s = 0; s < 10; ++s, ms += 1000) {
            const QByteArray t = "1000" + QByteArray::number(s).rightJustified(2, '0') + ".00";
            QByteArray chunk =
                    sentence("GPGGA," + t + ",5545.0720,N,03737.1040,E,1,08,0.9,152.0,M,14.0,M,,") +
                    sentence("GPRMC," + t + ",A,5545.0720,N,03737.1040,E,0.0,0.0,150324,,,A");
            if (s == 5) { // the link dropped for three seconds before this epoch
                index += "G " + QByteArray::number(ms - 3000) + ' ' +
                         QByteArray::number(log.size()) + ' ' + text + '\n';
                ms += 3000;
            }
            index += "R " + QByteArray::number(ms) + ' ' + QByteArray::number(log.size()) + ' ' +
                     QByteArray::number(chunk.size()) + '\n';
            log += chunk;
        }
        QFile f(path), idx(path + ".idx");
        QVERIFY(f.open(QIODevice::WriteOnly) && idx.open(QIODevice::WriteOnly));
        f.write(log);
        idx.write(index);
        f.close();
        idx.close();
        gnss::logview::LogView view(gnss::test::builtinRegistry());
        view.open(QFile::encodeName(path).toStdString());
        QVERIFY(view.waitUntilIndexed(60000));
        const auto events = view.events();
        const QByteArray csv = QByteArray::fromStdString(gnss::logview::eventsCsv(events));
        QVERIFY2(csv.contains(",link,"), csv.constData()); // the gap is there, with its words
        for (const QByteArray &line : csv.split('\n')) {
            const QList<QByteArray> cells = line.trimmed().split(',');
            if (cells.size() < 5 || cells[3] != "link") continue;
            const QByteArray cell = line.mid(line.indexOf(",link,") + 6);
            QVERIFY2(!QByteArray("=+-@\t").contains(cell.front()), cell.constData());
            const QByteArray unquoted = cell.startsWith('"') ? cell.mid(1) : cell;
            QVERIFY2(!QByteArray("=+-@\t").contains(unquoted.front()), cell.constData());
        }
    }
};

QTEST_MAIN(TstUntrustedInput)
#include "tst_untrusted_input.moc"
