// The qualification report: its format by extension, the XHTML (well-formed, the identity,
// settings, limits, plots and one row per run), the runs as CSV, the campaign as JSON, the files
// written (HTML or PDF with the CSV and JSON beside it, the PDF's text found by pdftotext), and
// the plots painted into images.
#include "compare/accuracy.h"
#include "core/wgs84.h"
#include "qualify/plots.h"
#include "qualify/report.h"
#include "state/epoch.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QPainter>
#include <QProcess>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <QXmlStreamReader>
#include <cmath>

using namespace gnss;
using namespace gnss::qualify;

Q_DECLARE_METATYPE(std::optional<gnss::qualify::ReportFormat>)

namespace {

TtffRun fixedRun(ReceiverAction a, int i, double t, int sats = 9, double distance = 3.5) {
    TtffRun r;
    r.start = a;
    r.index = i;
    r.outcome = RunOutcome::Fixed;
    r.position = t - 1;
    r.fix2d = t - 0.5;
    r.fix3d = t;
    r.satellitesAtFix = sats;
    r.distanceM = distance;
    return r;
}

TtffRun timedOutRun(ReceiverAction a, int i) {
    TtffRun r;
    r.start = a;
    r.index = i;
    r.outcome = RunOutcome::TimedOut;
    return r;
}

// A position `northM` north and `eastM` east of the reference, 0.5 m above it.
Epoch epochAt(const compare::ReferencePoint &ref, FixType fix, double northM, double eastM) {
    Epoch e;
    e.fix = fix;
    const auto m = wgs84::metresPerDegree(ref.latDeg);
    e.lat = ref.latDeg + northM / m.north;
    e.lon = ref.lonDeg + eastM / m.east;
    e.altMsl = *ref.height + 0.5 - 14.0;
    e.geoidSep = 14.0;
    e.satsUsed = 10;
    return e;
}

// Two receivers: the NVS with cold runs of 30, 33, 35 and 40 s and one timeout (mean 34.5 s),
// hot runs of 1.5, 2 and 2.5 s, settings and an accuracy; the GeoStar with two cold runs.
ReportInput fixture() {
    ReportInput in;
    in.started = QDateTime(QDate(2024, 5, 14), QTime(9, 0, 0), Qt::UTC);
    in.ended = in.started.addSecs(3725);
    in.reference = compare::ReferencePoint{55.7558260, 37.6172999, 180.0};
    in.location = QStringLiteral("Moscow, roof of building 2");
    in.starts = {ReceiverAction::ColdStart, ReceiverAction::HotStart};
    in.runsPerStart = 5;
    in.timeoutS = 300;
    in.pauseS = 10;
    in.limits = {Limit{ReceiverAction::ColdStart, LimitStat::Mean, 60},
                 Limit{ReceiverAction::HotStart, LimitStat::Max, 1}};

    ReportReceiver nvs;
    nvs.name = QStringLiteral("NVS NV08C-RTK");
    nvs.model = QStringLiteral("NV08C-RTK");
    nvs.firmware = QStringLiteral("0424");
    nvs.port = QStringLiteral("/dev/ttyUSB0");
    nvs.baud = 115200;
    nvs.settings = {{QStringLiteral("Elevation mask"), QStringLiteral("5°")},
                    {QStringLiteral("Navigation rate"), QStringLiteral("1 Hz")}};
    int i = 0;
    for (double t : {30.0, 33.0, 35.0, 40.0})
        nvs.runs.push_back(fixedRun(ReceiverAction::ColdStart, ++i, t));
    nvs.runs.push_back(timedOutRun(ReceiverAction::ColdStart, ++i));
    i = 0;
    for (double t : {1.5, 2.0, 2.5}) nvs.runs.push_back(fixedRun(ReceiverAction::HotStart, ++i, t));
    compare::Accuracy accuracy(*in.reference);
    const double offsets[][2] = {{0.4, 0.1},   {-0.3, 0.2}, {0.1, -0.5},  {0.8, 0.6},
                                 {-0.2, -0.1}, {1.5, -1.0}, {0.05, 0.02}, {-0.6, 0.3}};
    for (const auto &o : offsets) accuracy.add(epochAt(*in.reference, FixType::Fix3D, o[0], o[1]));
    accuracy.add(epochAt(*in.reference, FixType::RtkFixed, 0.01, 0.005));
    nvs.accuracy = accuracy.report();
    nvs.horizontalErrors = accuracy.horizontalErrors();
    in.receivers.push_back(nvs);

    ReportReceiver geostar;
    geostar.name = QStringLiteral("GeoStar GeoS-5");
    geostar.port = QStringLiteral("simulated geostar");
    geostar.runs = {fixedRun(ReceiverAction::ColdStart, 1, 45),
                    timedOutRun(ReceiverAction::ColdStart, 2)};
    in.receivers.push_back(geostar);
    return in;
}

int runCount(const ReportInput &in) {
    int n = 0;
    for (const ReportReceiver &r : in.receivers) n += int(r.runs.size());
    return n;
}

bool isNear(QRgb c, QRgb target, int tolerance = 40) {
    return std::abs(qRed(c) - qRed(target)) <= tolerance &&
           std::abs(qGreen(c) - qGreen(target)) <= tolerance &&
           std::abs(qBlue(c) - qBlue(target)) <= tolerance;
}

int distinctColours(const QImage &image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

} // namespace

class TstQualifyReport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        // The numbers the checks look for, as an English-speaking user sees them.
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }

    void formatByExtension_data() {
        QTest::addColumn<QString>("path");
        QTest::addColumn<std::optional<ReportFormat>>("format");
        QTest::newRow("pdf") << "a.pdf" << std::optional(ReportFormat::Pdf);
        QTest::newRow("PDF") << "/tmp/A.PDF" << std::optional(ReportFormat::Pdf);
        QTest::newRow("html") << "r.html" << std::optional(ReportFormat::Html);
        QTest::newRow("htm") << "dir.x/r.htm" << std::optional(ReportFormat::Html);
        QTest::newRow("txt") << "r.txt" << std::optional<ReportFormat>();
        QTest::newRow("none") << "r" << std::optional<ReportFormat>();
        QTest::newRow("dot in folder") << "dir.pdf/r" << std::optional<ReportFormat>();
    }
    void formatByExtension() {
        QFETCH(QString, path);
        QFETCH(std::optional<ReportFormat>, format);
        QVERIFY(reportFormatOf(path) == format);
    }

    void htmlIsWellFormedAndComplete() {
        const ReportInput in = fixture();
        const QString html = reportHtml(in);
        QXmlStreamReader xml(html);
        int runRows = 0, images = 0, h2 = 0;
        QString firstImageSrc;
        QStringList h2Texts;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            if (xml.name() == QLatin1String("tr") &&
                xml.attributes().value(QLatin1String("class")) == QLatin1String("run"))
                ++runRows;
            if (xml.name() == QLatin1String("img")) {
                ++images;
                if (firstImageSrc.isEmpty())
                    firstImageSrc = xml.attributes().value(QLatin1String("src")).toString();
                QVERIFY(!xml.attributes().value(QLatin1String("alt")).isEmpty());
            }
            if (xml.name() == QLatin1String("h2")) {
                ++h2;
                h2Texts << xml.readElementText();
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString() +
                                             QStringLiteral(" at line %1").arg(xml.lineNumber())));
        QCOMPARE(runRows, runCount(in));
        // Comparison CDF, a CDF per receiver, the NVS's histogram and errors over time.
        QCOMPARE(images, 5);
        QVERIFY2(h2Texts.contains(QStringLiteral("#1 NVS NV08C-RTK")),
                 qPrintable(h2Texts.join('|')));
        QVERIFY(h2Texts.contains(QStringLiteral("#2 GeoStar GeoS-5")));
        QVERIFY(h2 >= 5);

        for (const char *s : {"NV08C-RTK",
                              "0424",
                              "/dev/ttyUSB0",
                              "115200",
                              "Elevation mask",
                              "5°",
                              "Navigation rate",
                              "1 Hz",
                              "No settings were read",
                              ">pass<",
                              ">fail<",
                              "Median",
                              "34.5",
                              "Moscow, roof of building 2",
                              "55.7558260",
                              "37.6172999",
                              "2024-05-14 09:00:00 UTC",
                              "2024-05-14 10:02:05 UTC",
                              "1 h 2 min 5 s",
                              "CEP95",
                              "2DRMS"})
            QVERIFY2(html.contains(QString::fromUtf8(s)), s);
        QVERIFY(!html.contains(QLatin1String("&nbsp;")));

        const QString prefix = QStringLiteral("data:image/png;base64,");
        QVERIFY(firstImageSrc.startsWith(prefix));
        QImage image;
        QVERIFY(image.loadFromData(
                QByteArray::fromBase64(firstImageSrc.mid(prefix.size()).toLatin1()), "PNG"));
        QCOMPARE(image.size(), QSize(900, 420));
        QVERIFY(distinctColours(image) > 3);
    }

    void aSingleReceiverHasNoComparisonAndNoReceiverColumn() {
        ReportInput in = fixture();
        in.receivers.resize(1);
        in.limits.clear();
        in.reference.reset();
        const QString html = reportHtml(in);
        QXmlStreamReader xml(html);
        int images = 0;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement() && xml.name() == QLatin1String("img")) ++images;
        }
        QVERIFY(!xml.hasError());
        QCOMPARE(images, 3); // the CDF, the histogram and the errors over time
        QVERIFY(!html.contains(QLatin1String(">pass<")));
        QVERIFY(!html.contains(QLatin1String("#1 ")));
        QVERIFY(html.contains(QLatin1String("<th>Start</th><th>Run</th>")));
    }

    void textsAreEscaped() {
        ReportInput in = fixture();
        in.receivers[0].settings.push_back({QStringLiteral("<Mode>"), QStringLiteral("a & b")});
        in.location = QStringLiteral("\"x\" < y");
        const QString html = reportHtml(in);
        QXmlStreamReader xml(html);
        while (!xml.atEnd()) xml.readNext();
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(html.contains(QLatin1String("&lt;Mode&gt;")));
        QVERIFY(html.contains(QLatin1String("a &amp; b")));
    }

    void lengthsInTheUnitGiven() {
        ReportInput in = fixture();
        in.length = {QStringLiteral("ft"), 3.28084};
        const QString html = reportHtml(in);
        QVERIFY(html.contains(QStringLiteral("height 590.551\u00a0ft"))); // 180 m
        QVERIFY(html.contains(QStringLiteral("Distance, ft")));
        QVERIFY(html.contains(QStringLiteral(">11.5<"))); // 3.5 m
    }

    void csvHasOneLinePerRun() {
        const ReportInput in = fixture();
        const QString csv = QString::fromUtf8(runsCsv(in));
        QStringList lines = csv.split(QStringLiteral("\r\n"));
        QCOMPARE(lines.takeLast(), QString()); // ends with a line break
        QCOMPARE(lines.size(), 1 + runCount(in));
        QCOMPARE(lines[0], QStringLiteral("receiver,start,run,outcome,position_s,fix_2d_s,ttff_s,"
                                          "dgnss_s,rtk_float_s,rtk_fixed_s,satellites,distance_m"));
        QCOMPARE(lines[2],
                 QStringLiteral("NVS NV08C-RTK,cold,2,fixed,32.000,32.500,33.000,,,,9,3.500"));
        QCOMPARE(lines[5], QStringLiteral("NVS NV08C-RTK,cold,5,timeout,,,,,,,,"));
        QCOMPARE(lines[6].section(',', 0, 6),
                 QStringLiteral("NVS NV08C-RTK,hot,1,fixed,0.500,1.000,1.500"));
        QVERIFY(lines[9].startsWith(QLatin1String("GeoStar GeoS-5,cold,1,fixed,")));
    }

    void csvQuotesFields() {
        ReportInput in = fixture();
        in.receivers[1].name = QStringLiteral("Rover \"B\", roof");
        const QString csv = QString::fromUtf8(runsCsv(in));
        QVERIFY(csv.contains(QStringLiteral("\"Rover \"\"B\"\", roof\",cold,1,fixed,")));
    }

    void campaignJsonParses() {
        const ReportInput in = fixture();
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(campaignJson(in), &error);
        QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
        const QJsonObject o = doc.object();
        QCOMPARE(o["started"].toString(), QStringLiteral("2024-05-14T09:00:00Z"));
        QCOMPARE(o["location"].toString(), QStringLiteral("Moscow, roof of building 2"));
        QCOMPARE(o["ended"].toString(), QStringLiteral("2024-05-14T10:02:05Z"));
        QCOMPARE(o["plan"].toObject()["starts"].toArray(), QJsonArray({"cold", "hot"}));
        QCOMPARE(o["plan"].toObject()["runs"].toInt(), 5);
        QCOMPARE(o["plan"].toObject()["timeout_s"].toDouble(), 300.0);
        QCOMPARE(o["reference"].toObject()["height"].toDouble(), 180.0);
        const QJsonArray receivers = o["receivers"].toArray();
        QCOMPARE(receivers.size(), 2);
        const QJsonObject nvs = receivers[0].toObject();
        QCOMPARE(nvs["name"].toString(), QStringLiteral("NVS NV08C-RTK"));
        QCOMPARE(nvs["firmware"].toString(), QStringLiteral("0424"));
        QCOMPARE(nvs["baud"].toInt(), 115200);
        QCOMPARE(nvs["settings"].toArray()[0].toObject()["value"].toString(), QStringLiteral("5°"));
        const QJsonObject cold = nvs["starts"].toObject()["cold"].toObject();
        QCOMPARE(cold["runs"].toInt(), 5);
        QCOMPARE(cold["timeouts"].toInt(), 1);
        QCOMPARE(cold["ttff_s"].toObject()["mean"].toDouble(), 34.5);
        QCOMPARE(nvs["runs"].toArray().size(), 8);
        const QJsonArray limits = nvs["limits"].toArray();
        QCOMPARE(limits.size(), 2);
        QCOMPARE(limits[0].toObject()["pass"].toBool(), true);
        QCOMPARE(limits[1].toObject()["pass"].toBool(), false);
        QCOMPARE(limits[1].toObject()["value_s"].toDouble(), 2.5);
        const QJsonObject accuracy = nvs["accuracy"].toObject();
        QCOMPARE(accuracy["positions"].toInt(), 9);
        QVERIFY(accuracy["horizontal_m"].toObject()["cep95"].toDouble() > 0);
        const QJsonObject geostar = receivers[1].toObject();
        QVERIFY(geostar["baud"].isNull());
        QVERIFY(!geostar.contains("accuracy"));
        QCOMPARE(geostar["limits"].toArray()[1].toObject()["pass"].toBool(), false);
    }

    void writesHtmlAndPdfWithTheRunsBeside_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("html") << "report.html";
        QTest::newRow("pdf") << "campaign.2024.PDF";
    }
    void writesHtmlAndPdfWithTheRunsBeside() {
        QFETCH(QString, name);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(name);
        const QString base = path.left(path.lastIndexOf('.'));
        QString error;
        const QStringList written = writeReport(fixture(), path, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(written, QStringList({path, base + ".csv", base + ".json"}));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 3);
        QFile report(path);
        QVERIFY(report.open(QIODevice::ReadOnly));
        const QByteArray bytes = report.readAll();
        QFile csv(base + ".csv");
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll(), runsCsv(fixture()));
        QFile json(base + ".json");
        QVERIFY(json.open(QIODevice::ReadOnly));
        QVERIFY(!QJsonDocument::fromJson(json.readAll()).isNull());
        if (name.endsWith(QLatin1String(".html"))) {
            QVERIFY(bytes.startsWith("<!DOCTYPE html>"));
            QVERIFY(bytes.contains("NV08C-RTK"));
            return;
        }
        QVERIFY(bytes.startsWith("%PDF"));
        const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
        if (pdftotext.isEmpty()) QSKIP("pdftotext is not installed: the PDF's text is not checked");
        QProcess process;
        process.start(pdftotext, {QStringLiteral("-layout"), path, QStringLiteral("-")});
        QVERIFY(process.waitForFinished(20000));
        QCOMPARE(process.exitCode(), 0);
        const QString text = QString::fromUtf8(process.readAllStandardOutput());
        for (const char *s : {"Receiver qualification report", "NV08C-RTK", "0424", "115200",
                              "Elevation mask", "Median", "34.5", "fail", "GeoStar GeoS-5"})
            QVERIFY2(text.contains(QLatin1String(s)),
                     qPrintable(QStringLiteral("\"%1\" not in the PDF's text:\n%2").arg(s, text)));
    }

    void refusesAnotherExtension() {
        QTemporaryDir dir;
        QString error;
        const QString path = dir.filePath(QStringLiteral("report.txt"));
        QVERIFY(writeReport(fixture(), path, &error).isEmpty());
        QVERIFY2(error.contains(QLatin1String("report.txt")), qPrintable(error));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void anUnwritableFolderIsAnError() {
        QString error;
        const QString path = QStringLiteral("/nonexistent-folder-gnss/report.html");
        QVERIFY(writeReport(fixture(), path, &error).isEmpty());
        QVERIFY2(error.contains(path), qPrintable(error));
    }

    void seriesPerReceiverAndStart() {
        ReportInput in = fixture();
        auto series = cdfSeriesOf(in.receivers);
        QCOMPARE(series.size(), std::size_t(3));
        QCOMPARE(series[0].label, QStringLiteral("#1 cold"));
        QCOMPARE(series[0].seconds, (std::vector<double>{30, 33, 35, 40}));
        QCOMPARE(series[1].label, QStringLiteral("#1 hot"));
        QCOMPARE(series[2].label, QStringLiteral("#2 cold"));
        QVERIFY(series[0].colour != series[1].colour && series[1].colour != series[2].colour);
        in.receivers.resize(1);
        series = cdfSeriesOf(in.receivers);
        QCOMPARE(series.size(), std::size_t(2));
        QCOMPARE(series[0].label, QStringLiteral("cold"));
    }

    // A single series: the step line reaches 100 % (the top of the plot) after its last time and
    // stays there to the right; nothing of its colour in the lower half out there.
    void cdfReachesTheTopAfterTheLastRun() {
        QImage image(900, 420, QImage::Format_RGB32);
        image.fill(Qt::white);
        const QRgb blue = qRgb(0, 0, 255);
        {
            QPainter p(&image);
            paintCdf(p, QRectF(image.rect()),
                     {{QStringLiteral("cold"), QColor(blue), {10, 20, 30}}}, Qt::black,
                     QColor(220, 220, 220));
        }
        QVERIFY(distinctColours(image) > 3);
        const int x = image.width() * 9 / 10;
        int top = -1, lowest = -1;
        for (int y = 0; y < image.height(); ++y)
            if (isNear(image.pixel(x, y), blue)) {
                if (top < 0) top = y;
                lowest = y;
            }
        QVERIFY2(top >= 0, "no series colour right of the last run");
        QVERIFY2(top < image.height() / 6, qPrintable(QString::number(top)));
        QVERIFY2(lowest < image.height() / 6, qPrintable(QString::number(lowest)));
        // Before the first run the share is 0: the series lies on the bottom axis there.
        const int left = image.width() / 10;
        int blueLeft = -1;
        for (int y = image.height() / 3; y < image.height(); ++y)
            if (isNear(image.pixel(left, y), blue)) blueLeft = y;
        QVERIFY2(blueLeft > image.height() * 2 / 3, qPrintable(QString::number(blueLeft)));
    }

    void histogramPaintsBarsAndEmptyInputsDoNotCrash() {
        QImage image(900, 420, QImage::Format_RGB32);
        image.fill(Qt::white);
        const QRgb green = qRgb(0, 160, 0);
        {
            QPainter p(&image);
            paintHistogram(p, QRectF(image.rect()), {0.1, 0.2, 0.2, 0.3, 0.3, 0.3, 0.5, 0.9, 4.0},
                           QStringLiteral("m"), 1.0, QColor(green), Qt::black,
                           QColor(220, 220, 220), 0.3, 0.8);
        }
        int barPixels = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) barPixels += image.pixel(x, y) == green;
        QVERIFY2(barPixels > 1000, qPrintable(QString::number(barPixels)));

        for (const QSize size : {QSize(900, 420), QSize(4, 4)}) {
            QImage empty(size, QImage::Format_RGB32);
            empty.fill(Qt::white);
            QPainter p(&empty);
            paintHistogram(p, QRectF(empty.rect()), {}, QStringLiteral("ft"), 3.28084, Qt::green,
                           Qt::black, Qt::gray);
            paintCdf(p, QRectF(empty.rect()), {}, Qt::black, Qt::gray);
            paintCdf(p, QRectF(empty.rect()), {{QStringLiteral("hot"), Qt::red, {}}}, Qt::black,
                     Qt::gray);
            paintHistogram(p, QRectF(empty.rect()), {0, 0, 0}, QStringLiteral("m"), 1.0, Qt::green,
                           Qt::black, Qt::gray);
            p.end();
            if (size.width() > 100) QVERIFY(distinctColours(empty) > 1); // the axes and a text
        }
    }

    // Errors over time: a horizontal error that jumps from 1 m to 4 m half way is drawn low on
    // the left and high on the right; the vertical where there are heights only; a long series
    // and empty ones paint without trouble.
    void errorsOverTimeFollowTheEpochs() {
        QImage image(900, 420, QImage::Format_RGB32);
        image.fill(Qt::white);
        const QRgb blue = qRgb(0, 0, 255), orange = qRgb(255, 127, 14);
        std::vector<double> horizontal(200, 1.0), vertical(200, std::nan(""));
        for (std::size_t i = 100; i < 200; ++i) horizontal[i] = 4.0;
        for (std::size_t i = 0; i < 50; ++i) vertical[i] = 2.0;
        {
            QPainter p(&image);
            paintErrorSeries(p, QRectF(image.rect()), horizontal, vertical, QStringLiteral("m"),
                             1.0, QColor(blue), QColor(orange), Qt::black, QColor(220, 220, 220));
        }
        // Rows of column x whose pixel is mostly that colour (antialiased: partly white).
        auto rowsOf = [&](int x, QRgb colour) {
            std::vector<int> rows;
            for (int y = 0; y < image.height(); ++y) {
                const QRgb c = image.pixel(x, y);
                const int d = std::abs(qRed(c) - qRed(colour)) +
                              std::abs(qGreen(c) - qGreen(colour)) +
                              std::abs(qBlue(c) - qBlue(colour));
                if (d < 200) rows.push_back(y);
            }
            return rows;
        };
        const auto left = rowsOf(image.width() * 3 / 10, blue);
        const auto right = rowsOf(image.width() * 8 / 10, blue);
        QVERIFY(!left.empty() && !right.empty());
        QVERIFY2(left.front() > right.front() + image.height() / 4,
                 qPrintable(QString("%1 %2").arg(left.front()).arg(right.front())));
        QVERIFY(!rowsOf(image.width() * 2 / 10, orange).empty()); // heights at the start
        QVERIFY(rowsOf(image.width() * 7 / 10, orange).empty());  // none later
        std::vector<double> day(86400, 0.5);
        for (const QSize size : {QSize(900, 420), QSize(4, 4)}) {
            QImage other(size, QImage::Format_RGB32);
            QPainter p(&other);
            paintErrorSeries(p, QRectF(other.rect()), day, {}, QStringLiteral("ft"), 3.28084,
                             Qt::blue, Qt::red, Qt::black, Qt::gray);
            paintErrorSeries(p, QRectF(other.rect()), {}, {}, QStringLiteral("m"), 1.0, Qt::blue,
                             Qt::red, Qt::black, Qt::gray);
        }
    }
};

QTEST_MAIN(TstQualifyReport)
#include "tst_qualify_report.moc"
