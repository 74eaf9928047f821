// Exports read back by someone else: GPX and KML through Debian's gpsbabel give as many points
// as `gnss-cli epochs` has positions, each within 1e-7° of it; CSV has a row per epoch; the NMEA
// of a range is the file's bytes. Skips the gpsbabel part when gpsbabel is not installed.
#include "logview_files.h"
#include "logview_reference.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QXmlStreamReader>

#include <optional>

using namespace gnss;
using namespace gnss::logview;

namespace {

QByteArray run(const QString &program, const QStringList &args, int *code = nullptr) {
    QProcess p;
    p.start(program, args);
    p.waitForFinished(120000);
    if (code) *code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    return p.readAllStandardOutput();
}

// (lat, lon) of every epoch `gnss-cli epochs` prints with a position.
QList<QPair<double, double>> epochPositions(const QString &file) {
    QList<QPair<double, double>> out;
    for (const QByteArray &line : run(GNSS_CLI_PATH, {"epochs", file}).split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        if (o["lat"].isDouble() && o["lon"].isDouble())
            out.append({o["lat"].toDouble(), o["lon"].toDouble()});
    }
    return out;
}

// Epochs `first`..`last` of `view` exported as `format`; nothing when the export failed.
std::optional<std::string> exported(LogView &view, ExportFormat format, int first, int last) {
    std::string out;
    if (!view.exportRange(format, first, last, [&](std::string_view b) {
            out += b;
            return true;
        }))
        return std::nullopt;
    return out;
}

} // namespace

class TstLogviewExport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    DialectRegistry registry_ = makeBuiltinRegistry();

private slots:
    void gpsbabelReadsGpxAndKml_data() {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("log");
        for (const char *f : {"gpx", "kml"})
            for (const char *log : {"scenario", "generated 10 Hz", "nvs"})
                QTest::newRow((std::string(f) + ", " + log).c_str()) << f << log;
    }
    void gpsbabelReadsGpxAndKml() {
        QFETCH(QString, format);
        QFETCH(QString, log);
        const QString gpsbabel = QStandardPaths::findExecutable("gpsbabel");
        if (gpsbabel.isEmpty()) QSKIP("gpsbabel is not installed (apt-get install gpsbabel)");
        const QString in = dir_.filePath("in.nmea"), out = dir_.filePath("out." + format);
        std::string text = test::namedLog(log.toStdString());
        if (log == "generated 10 Hz") text.resize(text.find('\n', 400000) + 1);
        QVERIFY(test::writeFile(in.toStdString(), text));
        int code = -1;
        run(GNSS_CLI_PATH, {"export", "--format", format, in, "-o", out}, &code);
        QCOMPARE(code, 0);
        const QByteArray back =
                run(gpsbabel, {"-i", format, "-f", out, "-o", "gpx", "-F", "-"}, &code);
        QCOMPARE(code, 0);
        static const QRegularExpression pt(R"re(<trkpt lat="([-0-9.]+)" lon="([-0-9.]+)")re");
        QList<QPair<double, double>> points;
        for (auto it = pt.globalMatch(QString::fromUtf8(back)); it.hasNext();) {
            const auto m = it.next();
            points.append({m.captured(1).toDouble(), m.captured(2).toDouble()});
        }
        const auto expected = epochPositions(in);
        QVERIFY(expected.size() > 50);
        QCOMPARE(points.size(), expected.size());
        for (int i = 0; i < points.size(); ++i) {
            QVERIFY2(std::abs(points[i].first - expected[i].first) < 1e-7 &&
                             std::abs(points[i].second - expected[i].second) < 1e-7,
                     qPrintable(QString("point %1").arg(i)));
        }
    }

    // A log may be called anything: markup, control bytes, bytes that are no UTF-8. The GPX and
    // KML stay well formed, the name's markup and its good characters kept as they were.
    void anyNameGivesWellFormedXml_data() {
        QTest::addColumn<int>("format");
        QTest::newRow("gpx") << int(ExportFormat::Gpx);
        QTest::newRow("kml") << int(ExportFormat::Kml);
    }
    void anyNameGivesWellFormedXml() {
        QFETCH(int, format);
        const std::string p = dir_.filePath("named.nmea").toStdString();
        QVERIFY(test::writeFile(p, test::scenarioLog({})));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        const std::string name = "a\x01"
                                 "b\x1b[31m\xff\xfe<&>\"\xc3\xa9\xed\xa0\x80\xef\xbf\xbe z";
        std::string out;
        QVERIFY(view.exportRange(
                ExportFormat(format), 0, 10,
                [&](std::string_view b) {
                    out += b;
                    return true;
                },
                name));
        QXmlStreamReader x(QByteArray::fromStdString(out));
        QString shown;
        while (!x.atEnd()) {
            x.readNext();
            if (x.isStartElement() && x.name() == QLatin1String("name") && shown.isEmpty())
                shown = x.readElementText();
        }
        QVERIFY2(!x.hasError(), qPrintable(x.errorString()));
        const QChar r(0xFFFD);
        QCOMPARE(shown, QString("a") + r + "b" + r + "[31m" + r + r + "<&>\"" + QChar(0xE9) + r +
                                r + r + r + r + r + " z");
    }

    void csvHasARowPerEpoch() {
        const std::string text = test::scenarioLog({});
        const std::string p = dir_.filePath("csv.nmea").toStdString();
        QVERIFY(test::writeFile(p, text));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        const auto csv = exported(view, ExportFormat::Csv, 0, 599);
        QVERIFY(csv);
        const QStringList lines = QString::fromStdString(*csv).split("\r\n", Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 601);
        QCOMPARE(lines[0], QString("epoch,time,host_time,fix,lat,lon,alt_msl,sats_used,hdop,"
                                   "mean_snr,speed_mps,station,offset,length,flags"));
        for (const QString &l : lines) QCOMPARE(l.count(','), 14);
        QVERIFY(lines[301].contains("gap"));
        QVERIFY(lines[1].startsWith("0,2024-03-15T10:00:00.000Z,,none,,,120.500,0,"));
        // Lengths add up to the file.
        std::uint64_t total = 0;
        for (int i = 1; i < lines.size(); ++i) total += lines[i].split(',')[13].toULongLong();
        QCOMPARE(total, std::uint64_t(text.size()));
    }

    void nmeaOfARangeIsTheFilesBytes_data() {
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::newRow("whole") << 0 << 599;
        QTest::newRow("first epoch") << 0 << 0;
        QTest::newRow("middle") << 123 << 321;
        QTest::newRow("last epoch") << 599 << 599;
    }
    void nmeaOfARangeIsTheFilesBytes() {
        QFETCH(int, first);
        QFETCH(int, last);
        const std::string text = test::scenarioLog({});
        const std::string p = dir_.filePath("range.nmea").toStdString();
        QVERIFY(test::writeFile(p, text));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        const auto nmea = exported(view, ExportFormat::Nmea, first, last);
        QVERIFY(nmea);
        const std::string &out = *nmea;
        const std::uint64_t from = view.epoch(first)->offset, to = view.epochEnd(last);
        QCOMPARE(out, text.substr(from, to - from));
        // The range decodes to its epochs (the first one's sky may be partial, not its count).
        QCOMPARE(test::frontToBack(out, registry_).size(), std::size_t(last - first + 1));
    }
};

QTEST_APPLESS_MAIN(TstLogviewExport)
#include "tst_logview_export.moc"
