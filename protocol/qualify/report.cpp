// The qualification report: one self-contained XHTML document (plots as data: PNG images), or a
// PDF laid out from the same HTML by QTextDocument on a QPdfWriter (the plots as the document's
// resources); beside it every run as CSV and the whole campaign as JSON.
#include "qualify/report.h"

#include "core/dialect.h"
#include "core/fix_type.h"
#include "core/json_writer.h"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QLocale>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>
#include <QUrl>

#include <cmath>
#include <cstdio>

namespace gnss::qualify {

namespace {

// The plots' size in the HTML (CSS pixels); the PDF's are drawn at twice that.
constexpr int kReportPlotWidth = 900, kReportPlotHeight = 420;

// How the HTML carries its plots: embedded as data: URIs (the HTML file), or by names the
// caller registers as resources of a QTextDocument (the PDF: it loads no data: URI).
enum class ReportImageMode { Embedded, Resources };

// The texts' context for translation: every text of the report is the user's language.
class ReportTr {
    Q_DECLARE_TR_FUNCTIONS(gnss::qualify::Report)
};

struct ReportImage {
    QString name;
    QImage image;
};

QString reportEscaped(const QString &s) {
    return s.toHtmlEscaped();
}

QString reportDash() {
    return QStringLiteral("\u2014");
}

QLocale reportLocale() {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

// Seconds with one decimal in the user's notation, or a dash.
QString reportSeconds(const std::optional<double> &s) {
    return s && std::isfinite(*s) ? reportLocale().toString(*s, 'f', 1) : reportDash();
}

// A length in the unit of the preferences, its symbol after a no-break space.
QString reportLength(double metres, const LengthUnit &unit, int decimals = 3) {
    return reportLocale().toString(metres * unit.perMetre, 'f', decimals) + QChar(0x00a0) +
           unit.symbol;
}

QString reportTimestamp(const QDateTime &t) {
    if (!t.isValid()) return reportDash();
    return t.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) + QStringLiteral(" UTC");
}

QString reportDuration(qint64 seconds) {
    if (seconds < 0) return reportDash();
    const qint64 h = seconds / 3600, m = seconds / 60 % 60, s = seconds % 60;
    if (h) return ReportTr::tr("%1 h %2 min %3 s").arg(h).arg(m).arg(s);
    if (m) return ReportTr::tr("%1 min %2 s").arg(m).arg(s);
    return ReportTr::tr("%1 s").arg(s);
}

QString reportOutcome(RunOutcome o) {
    switch (o) {
    case RunOutcome::Fixed: return ReportTr::tr("fixed");
    case RunOutcome::TimedOut: return ReportTr::tr("timeout");
    case RunOutcome::Lost: return ReportTr::tr("lost");
    }
    return {};
}

QString reportStatName(LimitStat s) {
    switch (s) {
    case LimitStat::Mean: return ReportTr::tr("mean");
    case LimitStat::Median: return ReportTr::tr("median");
    case LimitStat::P90: return ReportTr::tr("P90");
    case LimitStat::P95: return ReportTr::tr("P95");
    case LimitStat::Max: return ReportTr::tr("max");
    }
    return {};
}

QString reportFixName(FixType f) {
    switch (f) {
    case FixType::None: return ReportTr::tr("No fix");
    case FixType::Estimated: return ReportTr::tr("Estimated");
    case FixType::Fix2D: return ReportTr::tr("2D");
    case FixType::Fix3D: return ReportTr::tr("3D");
    case FixType::Dgnss: return ReportTr::tr("DGNSS");
    case FixType::RtkFloat: return ReportTr::tr("RTK float");
    case FixType::RtkFixed: return ReportTr::tr("RTK fixed");
    case FixType::Manual: return ReportTr::tr("Manual");
    case FixType::Simulator: return ReportTr::tr("Simulator");
    }
    return {};
}

QString reportOrDash(const QString &s) {
    return s.isEmpty() ? reportDash() : s;
}

// A receiver as the tables name it: "#2 NAME" when there are several.
QString reportReceiverTitle(const ReportInput &in, std::size_t i) {
    const QString name = reportOrDash(in.receivers[i].name);
    return in.receivers.size() > 1 ? QStringLiteral("#%1 %2").arg(i + 1).arg(name) : name;
}

// A plot on white, `scale` times the report's plot size, in the report's colours.
const QColor kReportText(0x22, 0x22, 0x22), kReportGrid(0xdd, 0xdd, 0xdd),
        kReportFirst(0x1f, 0x77, 0xb4), kReportSecond(0xff, 0x7f, 0x0e);

template <class Paint> QImage reportPlotImage(int scale, Paint paint) {
    QImage image(kReportPlotWidth * scale, kReportPlotHeight * scale, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setBackground(Qt::white);
    paint(p, QRectF(image.rect()));
    return image;
}

QImage reportCdfImage(const std::vector<CdfSeries> &series, int scale) {
    return reportPlotImage(scale, [&](QPainter &p, const QRectF &area) {
        paintCdf(p, area, series, kReportText, kReportGrid);
    });
}

QImage reportHistogramImage(const ReportReceiver &r, const LengthUnit &unit, int scale) {
    const double cep50 = r.accuracy ? r.accuracy->cep50 : 0,
                 cep95 = r.accuracy ? r.accuracy->cep95 : 0;
    return reportPlotImage(scale, [&](QPainter &p, const QRectF &area) {
        paintHistogram(p, area, r.horizontalErrors, unit.symbol, unit.perMetre, kReportFirst,
                       kReportText, kReportGrid, cep50, cep95);
    });
}

QImage reportErrorSeriesImage(const ReportReceiver &r, const LengthUnit &unit, int scale) {
    return reportPlotImage(scale, [&](QPainter &p, const QRectF &area) {
        paintErrorSeries(p, area, r.horizontalErrors, r.verticalErrors, unit.symbol, unit.perMetre,
                         kReportFirst, kReportSecond, kReportText, kReportGrid);
    });
}

// Builds the report's XHTML: the sections in order, each an <h2>.
class ReportHtmlBuilder {
    Q_DECLARE_TR_FUNCTIONS(gnss::qualify::Report)

public:
    ReportHtmlBuilder(const ReportInput &in, ReportImageMode mode, double imageWidth)
        : in_(in), mode_(mode), imageWidth_(imageWidth) {}

    QString build();
    std::vector<ReportImage> takeImages() { return std::move(images_); }

private:
    void heading(const char *tag, const QString &text);
    void paragraph(const QString &text, const QString &cls = {});
    // A table with its column headers (none: a table of label and value rows).
    void openTable(const QStringList &headers, const QString &tableClass = {});
    void closeTable() { h_ += QStringLiteral("</tbody></table>\n"); }
    // A row of cells: plain texts, escaped here; numeric ones aligned right.
    void row(const QStringList &cells, const QString &rowClass = {},
             const std::vector<QString> &cellClasses = {});
    // A two-column row: the label as a header cell.
    void pair(const QString &label, const QString &value);
    void image(const QImage &image, const QString &name, const QString &alt);

    void conditions();
    void comparison();
    void receiver(std::size_t i);
    void ttffTable(const ReportReceiver &r);
    void limits(const ReportReceiver &r);
    void accuracy(const ReportReceiver &r);
    void runs();

    const ReportInput &in_;
    ReportImageMode mode_;
    double imageWidth_;
    int scale_ = 1;
    QString h_;
    std::vector<ReportImage> images_;
};

void ReportHtmlBuilder::heading(const char *tag, const QString &text) {
    h_ += QStringLiteral("<%1>%2</%1>\n").arg(QLatin1String(tag), reportEscaped(text));
}

void ReportHtmlBuilder::paragraph(const QString &text, const QString &cls) {
    if (cls.isEmpty())
        h_ += QStringLiteral("<p>%1</p>\n").arg(reportEscaped(text));
    else
        h_ += QStringLiteral("<p class=\"%1\">%2</p>\n").arg(cls, reportEscaped(text));
}

void ReportHtmlBuilder::openTable(const QStringList &headers, const QString &tableClass) {
    h_ += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\"%1>")
                  .arg(tableClass.isEmpty() ? QString()
                                            : QStringLiteral(" class=\"%1\"").arg(tableClass));
    if (!headers.isEmpty()) {
        h_ += QStringLiteral("<thead><tr>");
        for (const QString &t : headers) h_ += QStringLiteral("<th>%1</th>").arg(reportEscaped(t));
        h_ += QStringLiteral("</tr></thead>");
    }
    h_ += QStringLiteral("<tbody>\n");
}

void ReportHtmlBuilder::row(const QStringList &cells, const QString &rowClass,
                            const std::vector<QString> &cellClasses) {
    h_ += rowClass.isEmpty() ? QStringLiteral("<tr>")
                             : QStringLiteral("<tr class=\"%1\">").arg(rowClass);
    for (qsizetype i = 0; i < cells.size(); ++i) {
        QString cls = std::size_t(i) < cellClasses.size() ? cellClasses[std::size_t(i)] : QString();
        if (cls.isEmpty() && cells[i] == reportDash()) cls = QStringLiteral("num");
        if (cls.isEmpty()) {
            bool number = false;
            QString probe = cells[i];
            probe.remove(QChar(0x00a0) + in_.length.symbol);
            reportLocale().toDouble(probe, &number);
            if (number) cls = QStringLiteral("num");
        }
        h_ += cls.isEmpty() ? QStringLiteral("<td>") : QStringLiteral("<td class=\"%1\">").arg(cls);
        h_ += reportEscaped(cells[i]) + QStringLiteral("</td>");
    }
    h_ += QStringLiteral("</tr>\n");
}

void ReportHtmlBuilder::pair(const QString &label, const QString &value) {
    h_ += QStringLiteral("<tr><th class=\"label\">%1</th><td>%2</td></tr>\n")
                  .arg(reportEscaped(label), reportEscaped(value));
}

void ReportHtmlBuilder::image(const QImage &image, const QString &name, const QString &alt) {
    if (mode_ == ReportImageMode::Embedded) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        image.save(&buffer, "PNG");
        h_ += QStringLiteral("<p><img src=\"data:image/png;base64,%1\" alt=\"%2\" width=\"%3\" "
                             "height=\"%4\" style=\"max-width: 100%; height: auto;\"/></p>\n")
                      .arg(QString::fromLatin1(png.toBase64()), reportEscaped(alt))
                      .arg(kReportPlotWidth)
                      .arg(kReportPlotHeight);
    } else {
        const int width = int(imageWidth_);
        const int height = int(imageWidth_ * image.height() / std::max(1, image.width()));
        h_ += QStringLiteral("<p><img src=\"%1\" alt=\"%2\" width=\"%3\" height=\"%4\"/></p>\n")
                      .arg(reportEscaped(name), reportEscaped(alt))
                      .arg(width)
                      .arg(height);
        images_.push_back({name, image});
    }
}

QString ReportHtmlBuilder::build() {
    scale_ = mode_ == ReportImageMode::Resources ? 2 : 1;
    const QString title = tr("Receiver qualification report");
    const QString language = reportEscaped(QLocale().bcp47Name());
    h_ = QStringLiteral("<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"%1\" "
                        "xml:lang=\"%1\">\n<head>\n<meta charset=\"utf-8\"/>\n")
                 .arg(language);
    h_ += QStringLiteral("<title>%1</title>\n").arg(reportEscaped(title));
    h_ += QStringLiteral(
            "<style>\n"
            "body { font-family: sans-serif; color: #222222; }\n"
            "h1 { font-size: 18pt; }\n"
            "h2 { font-size: 14pt; margin-top: 18px; border-bottom: 1px solid #888888; }\n"
            "h3 { font-size: 11pt; margin-top: 12px; }\n"
            "table { border-collapse: collapse; margin-bottom: 8px; }\n"
            "th, td { border: 1px solid #999999; padding: 2px 6px; }\n"
            "th { background-color: #eeeeee; text-align: left; }\n"
            "td.num { text-align: right; }\n"
            "table.runs th, table.runs td { font-size: 7.5pt; padding: 1px 3px; }\n"
            "td.pass { color: #1a7f37; }\n"
            "td.fail { color: #c62828; font-weight: bold; }\n"
            "p.note { color: #555555; }\n"
            "</style>\n</head>\n<body>\n");
    heading("h1", title);
    paragraph(tr("Generated %1 by GNSS Workbench")
                      .arg(reportTimestamp(QDateTime::currentDateTimeUtc())),
              QStringLiteral("note"));
    conditions();
    if (in_.receivers.size() > 1) comparison();
    for (std::size_t i = 0; i < in_.receivers.size(); ++i) receiver(i);
    runs();
    h_ += QStringLiteral("</body>\n</html>\n");
    return std::move(h_);
}

void ReportHtmlBuilder::conditions() {
    heading("h2", tr("Conditions"));
    openTable({});
    pair(tr("Started"), reportTimestamp(in_.started));
    pair(tr("Ended"), reportTimestamp(in_.ended));
    pair(tr("Duration"), in_.started.isValid() && in_.ended.isValid()
                                 ? reportDuration(in_.started.secsTo(in_.ended))
                                 : reportDash());
    QStringList starts;
    for (ReceiverAction a : in_.starts) starts << startName(a);
    pair(tr("Kinds of start"), starts.isEmpty() ? reportDash() : starts.join(QStringLiteral(", ")));
    pair(tr("Runs per start"),
         in_.runsPerStart > 0 ? QString::number(in_.runsPerStart) : reportDash());
    // Seconds as typed: 180, 0.5 (not rounded to a whole second).
    pair(tr("Timeout"), tr("%1 s").arg(reportLocale().toString(in_.timeoutS, 'g', 6)));
    pair(tr("Pause between runs"), tr("%1 s").arg(reportLocale().toString(in_.pauseS, 'g', 6)));
    QString reference = tr("none");
    if (in_.reference) {
        const QLocale l = reportLocale();
        reference = tr("latitude %1°, longitude %2°")
                            .arg(l.toString(in_.reference->latDeg, 'f', 7),
                                 l.toString(in_.reference->lonDeg, 'f', 7));
        reference += QStringLiteral(", ");
        reference += in_.reference->height
                             ? tr("height %1").arg(reportLength(*in_.reference->height, in_.length))
                             : tr("height none");
    }
    pair(tr("Reference point"), reference);
    pair(tr("Location"), reportOrDash(in_.location));
    closeTable();
}

void ReportHtmlBuilder::comparison() {
    heading("h2", tr("Comparison"));
    paragraph(tr("Time to first 3D fix in seconds, per receiver and kind of start."));
    openTable({tr("Receiver"), tr("Start"), tr("Runs"), tr("Fixed"), tr("Mean"), tr("Median"),
               tr("P95")});
    for (std::size_t i = 0; i < in_.receivers.size(); ++i) {
        for (const StartStats &s : statsOf(in_.receivers[i].runs)) {
            auto stat = [&s](double v) { return s.fixed ? reportSeconds(v) : reportDash(); };
            row({reportReceiverTitle(in_, i), startName(s.start), QString::number(s.runs),
                 QString::number(s.fixed), stat(s.ttff.mean), stat(s.ttff.median),
                 stat(s.ttff.p95)});
        }
    }
    closeTable();
    image(reportCdfImage(cdfSeriesOf(in_.receivers), scale_), QStringLiteral("cdf-all.png"),
          tr("Time to first fix, all receivers (CDF)"));
}

void ReportHtmlBuilder::receiver(std::size_t i) {
    const ReportReceiver &r = in_.receivers[i];
    heading("h2", reportReceiverTitle(in_, i));

    heading("h3", tr("Identity"));
    openTable({});
    pair(tr("Receiver"), reportOrDash(r.name));
    pair(tr("Model"), reportOrDash(r.model));
    pair(tr("Firmware"), reportOrDash(r.firmware));
    pair(tr("Port"), reportOrDash(r.port));
    pair(tr("Baud"), r.baud > 0 ? QString::number(r.baud) : reportDash());
    closeTable();

    heading("h3", tr("Settings"));
    if (r.settings.empty()) {
        paragraph(tr("No settings were read"));
    } else {
        openTable({tr("Setting"), tr("Value")});
        for (const auto &[label, value] : r.settings) pair(label, value);
        closeTable();
    }

    heading("h3", tr("Time to first fix"));
    ttffTable(r);
    const auto series = cdfSeriesOf({r});
    if (series.empty())
        paragraph(tr("No run has fixed yet"));
    else
        image(reportCdfImage(series, scale_), QStringLiteral("cdf-%1.png").arg(i),
              tr("Time to first fix of %1 (CDF)").arg(reportOrDash(r.name)));

    if (!in_.limits.empty()) limits(r);
    if (r.accuracy) accuracy(r);
}

void ReportHtmlBuilder::ttffTable(const ReportReceiver &r) {
    const auto stats = statsOf(r.runs);
    if (stats.empty()) {
        paragraph(tr("No runs"));
        return;
    }
    paragraph(tr("Seconds from the restart to the first 3D fix, of the runs that fixed."),
              QStringLiteral("note"));
    openTable({tr("Start"), tr("Runs"), tr("Fixed"), tr("Timeouts"), tr("Lost"), tr("Mean"),
               tr("Median"), tr("P90"), tr("P95"), tr("Min"), tr("Max")});
    for (const StartStats &s : stats) {
        auto stat = [&s](double v) { return s.fixed ? reportSeconds(v) : reportDash(); };
        row({startName(s.start), QString::number(s.runs), QString::number(s.fixed),
             QString::number(s.timeouts), QString::number(s.lost), stat(s.ttff.mean),
             stat(s.ttff.median), stat(s.p90), stat(s.ttff.p95), stat(s.ttff.min),
             stat(s.ttff.max)});
    }
    closeTable();
}

void ReportHtmlBuilder::limits(const ReportReceiver &r) {
    heading("h3", tr("Limits"));
    const auto results = checkLimits(in_.limits, r.runs);
    int failed = 0;
    openTable({tr("Limit"), tr("Measured"), tr("Result")});
    for (const LimitResult &l : results) {
        const QString limit = tr("%1 %2 \u2264 %3 s")
                                      .arg(startName(l.limit.start), reportStatName(l.limit.stat),
                                           reportLocale().toString(l.limit.maxSeconds, 'f', 1));
        const QString measured =
                l.value ? tr("%1 s").arg(reportSeconds(l.value)) : tr("no run fixed");
        failed += !l.pass;
        row({limit, measured, l.pass ? tr("pass") : tr("fail")}, {},
            {QString(), QStringLiteral("num"),
             l.pass ? QStringLiteral("pass") : QStringLiteral("fail")});
    }
    closeTable();
    paragraph(failed ? tr("%1 of %2 limits not met").arg(failed).arg(results.size())
                     : tr("All limits met"),
              QStringLiteral("note"));
}

void ReportHtmlBuilder::accuracy(const ReportReceiver &r) {
    const compare::AccuracyReport &a = *r.accuracy;
    const LengthUnit &u = in_.length;
    heading("h3", in_.reference ? tr("Accuracy against the reference point")
                                : tr("Accuracy about the mean position (no reference point)"));
    openTable({});
    pair(tr("Positions"), QString::number(a.positions));
    pair(tr("Bias east"), reportLength(a.biasEast, u));
    pair(tr("Bias north"), reportLength(a.biasNorth, u));
    pair(tr("Bias up"), a.biasUp ? reportLength(*a.biasUp, u) : reportDash());
    pair(tr("Horizontal mean"), reportLength(a.horizontal.mean, u));
    pair(tr("Horizontal median"), reportLength(a.horizontal.median, u));
    pair(tr("CEP50"), reportLength(a.cep50, u));
    pair(tr("CEP95"), reportLength(a.cep95, u));
    pair(tr("2DRMS"), reportLength(a.drms2, u));
    pair(tr("R95"), reportLength(a.horizontal.p95, u));
    pair(tr("Horizontal max"), reportLength(a.horizontal.max, u));
    if (a.heights) {
        pair(tr("Vertical mean"), reportLength(a.vertical.mean, u));
        pair(tr("Vertical median"), reportLength(a.vertical.median, u));
        pair(tr("Vertical 95 %"), reportLength(a.vertical.p95, u));
    }
    closeTable();

    paragraph(tr("Share of epochs within a horizontal distance of the reference point."),
              QStringLiteral("note"));
    QStringList headers{tr("Fix"), tr("Epochs")};
    for (double d : compare::kWithinMetres)
        headers << tr("\u2264 %1")
                           .arg(reportLocale().toString(d * u.perMetre, 'g', 3) + QChar(0x00a0) +
                                u.symbol);
    openTable(headers);
    auto shares = [this](const QString &label, const compare::WithinShares &w) {
        QStringList cells{label, QString::number(w.epochs)};
        for (double p : w.percent)
            cells << reportLocale().toString(p, 'f', 1) + QChar(0x00a0) + QLatin1Char('%');
        std::vector<QString> classes(std::size_t(cells.size()), QStringLiteral("num"));
        classes[0] = QStringLiteral("label");
        row(cells, {}, classes);
    };
    shares(tr("All"), a.within);
    for (const auto &[fix, w] : a.withinByFix) shares(reportFixName(fix), w);
    closeTable();

    if (!r.horizontalErrors.empty()) {
        const std::size_t index = images_.size();
        image(reportHistogramImage(r, u, scale_), QStringLiteral("histogram-%1.png").arg(index),
              tr("Horizontal error of %1 (histogram)").arg(reportOrDash(r.name)));
        image(reportErrorSeriesImage(r, u, scale_),
              QStringLiteral("errors-%1.png").arg(images_.size()),
              tr("Horizontal and vertical error of %1 over time").arg(reportOrDash(r.name)));
    }
}

void ReportHtmlBuilder::runs() {
    heading("h2", tr("Runs"));
    const bool several = in_.receivers.size() > 1;
    paragraph(tr("Seconds from the restart to the first fix of each kind; the satellites used "
                 "and the distance from the reference point at the first 3D fix."),
              QStringLiteral("note"));
    QStringList headers;
    if (several) headers << tr("Receiver");
    headers << tr("Start") << tr("Run") << tr("Outcome") << tr("Position") << tr("2D")
            << tr("3D (TTFF)") << tr("DGNSS") << tr("RTK float") << tr("RTK fixed")
            << tr("Satellites") << tr("Distance, %1").arg(in_.length.symbol);
    // A dozen columns: smaller, to fit the page's width (QTextDocument would break words).
    openTable(headers, QStringLiteral("runs"));
    bool any = false;
    for (std::size_t i = 0; i < in_.receivers.size(); ++i) {
        for (const TtffRun &run : in_.receivers[i].runs) {
            QStringList cells;
            if (several) cells << reportReceiverTitle(in_, i);
            cells << startName(run.start) << QString::number(run.index)
                  << reportOutcome(run.outcome) << reportSeconds(run.position)
                  << reportSeconds(run.fix2d) << reportSeconds(run.fix3d)
                  << reportSeconds(run.dgnss) << reportSeconds(run.rtkFloat)
                  << reportSeconds(run.rtkFixed)
                  << (run.satellitesAtFix ? QString::number(*run.satellitesAtFix) : reportDash())
                  << (run.distanceM ? reportLocale().toString(*run.distanceM * in_.length.perMetre,
                                                              'f', 1)
                                    : reportDash());
            row(cells, QStringLiteral("run"));
            any = true;
        }
    }
    closeTable();
    if (!any) paragraph(tr("No runs"));
}

// The report's HTML with its plots as `mode` says; the images to register for Resources.
QString reportHtmlWith(const ReportInput &in, ReportImageMode mode, double imageWidth,
                       std::vector<ReportImage> *images) {
    ReportHtmlBuilder b(in, mode, imageWidth);
    QString html = b.build();
    if (images) *images = b.takeImages();
    return html;
}

// The report laid out on A4 pages into `device`.
void reportPrintPdf(const ReportInput &in, QIODevice *device) {
    QPdfWriter writer(device);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setResolution(300);
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setTitle(ReportTr::tr("Receiver qualification report"));
    writer.setCreator(QStringLiteral("GNSS Workbench"));
    const QSizeF page = writer.pageLayout().paintRectPixels(writer.resolution()).size();
    // Images are sized in CSS pixels (96 a inch), the layout scales them to the device.
    const double imageWidth = std::floor(page.width() * 96.0 / writer.resolution()) - 24;
    std::vector<ReportImage> images;
    const QString html = reportHtmlWith(in, ReportImageMode::Resources, imageWidth, &images);

    QTextDocument doc;
    doc.documentLayout()->setPaintDevice(&writer);
    doc.setPageSize(page);
    QFont font = doc.defaultFont();
    font.setPointSizeF(9);
    // No ligatures ("fi" as one glyph would read back as U+FB01, and a search for "fix" would
    // miss it): Qt sets none with a letter spacing, this one a fraction of a device pixel.
    font.setLetterSpacing(QFont::AbsoluteSpacing, 0.05);
    doc.setDefaultFont(font);
    for (const ReportImage &i : images)
        doc.addResource(QTextDocument::ImageResource, QUrl(i.name), QVariant(i.image));
    doc.setHtml(html);
    doc.print(&writer);
}

bool reportSave(const QString &path, const QByteArray &bytes, QString *error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error) *error = ReportTr::tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

QString reportCsvField(const QString &s) {
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')) &&
        !s.contains(QLatin1Char('\n')) && !s.contains(QLatin1Char('\r')))
        return s;
    QString q = s;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

// A text as a JSON string (UTF-8: names, settings' values, the location in the user's language).
void reportJsonText(JsonWriter &w, const QString &s) {
    w.value(s.toStdString());
}

std::string reportIso(const QDateTime &t) {
    return t.toUTC().toString(Qt::ISODate).toStdString();
}

} // namespace

std::optional<ReportFormat> reportFormatOf(const QString &path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("pdf")) return ReportFormat::Pdf;
    if (suffix == QLatin1String("html") || suffix == QLatin1String("htm"))
        return ReportFormat::Html;
    return std::nullopt;
}

QString reportHtml(const ReportInput &in) {
    return reportHtmlWith(in, ReportImageMode::Embedded, kReportPlotWidth, nullptr);
}

QByteArray runsCsv(const ReportInput &in) {
    QByteArray out("receiver,start,run,outcome,position_s,fix_2d_s,ttff_s,dgnss_s,rtk_float_s,"
                   "rtk_fixed_s,satellites,distance_m\r\n");
    auto number = [](const std::optional<double> &v) {
        return v && std::isfinite(*v) ? QByteArray::number(*v, 'f', 3) : QByteArray();
    };
    for (const ReportReceiver &r : in.receivers) {
        const QByteArray name = reportCsvField(r.name).toUtf8();
        for (const TtffRun &run : r.runs) {
            QByteArrayList cells{name,
                                 QByteArray::fromStdString(std::string(toString(run.start))),
                                 QByteArray::number(run.index),
                                 QByteArray::fromStdString(std::string(toString(run.outcome))),
                                 number(run.position),
                                 number(run.fix2d),
                                 number(run.fix3d),
                                 number(run.dgnss),
                                 number(run.rtkFloat),
                                 number(run.rtkFixed),
                                 run.satellitesAtFix ? QByteArray::number(*run.satellitesAtFix)
                                                     : QByteArray(),
                                 number(run.distanceM)};
            out += cells.join(',') + "\r\n";
        }
    }
    return out;
}

QByteArray campaignJson(const ReportInput &in) {
    std::string out;
    JsonWriter w(out);
    w.beginObject();
    w.key("started");
    in.started.isValid() ? w.value(reportIso(in.started)) : w.null();
    w.key("ended");
    in.ended.isValid() ? w.value(reportIso(in.ended)) : w.null();
    w.key("location");
    reportJsonText(w, in.location);
    w.key("plan").beginObject();
    w.key("starts").beginArray();
    for (ReceiverAction a : in.starts) w.value(toString(a));
    w.endArray();
    w.field("runs", in.runsPerStart).field("timeout_s", in.timeoutS).field("pause_s", in.pauseS);
    w.endObject();
    w.key("reference");
    if (in.reference)
        w.beginObject()
                .field("lat", in.reference->latDeg)
                .field("lon", in.reference->lonDeg)
                .field("height", in.reference->height)
                .endObject();
    else
        w.null();
    w.key("receivers").beginArray();
    for (const ReportReceiver &r : in.receivers) {
        w.beginObject();
        for (const auto &[k, v] :
             {std::pair("name", &r.name), std::pair("model", &r.model),
              std::pair("firmware", &r.firmware), std::pair("port", &r.port)}) {
            w.key(k);
            reportJsonText(w, *v);
        }
        w.key("baud");
        r.baud > 0 ? w.value(r.baud) : w.null();
        w.key("settings").beginArray();
        for (const auto &[label, value] : r.settings) {
            w.beginObject().key("label");
            reportJsonText(w, label);
            w.key("value");
            reportJsonText(w, value);
            w.endObject();
        }
        w.endArray();
        writeCampaignJson(w, r.runs);
        writeLimitsJson(w, checkLimits(in.limits, r.runs));
        if (r.accuracy && in.reference) {
            w.key("accuracy");
            r.accuracy->writeJson(w, *in.reference);
        }
        w.endObject();
    }
    w.endArray();
    w.endObject();
    return QByteArray::fromStdString(out);
}

QStringList writeReport(const ReportInput &in, const QString &path, QString *error) {
    auto fail = [error](const QString &why) {
        if (error) *error = why;
        return QStringList();
    };
    const auto format = reportFormatOf(path);
    if (!format) return fail(ReportTr::tr("%1: a report is .pdf or .html").arg(path));
    const QFileInfo info(path);
    const QString base = path.left(path.size() - info.suffix().size() - 1);
    const QString csvPath = base + QStringLiteral(".csv");
    const QString jsonPath = base + QStringLiteral(".json");
    for (const QString &beside : {csvPath, jsonPath})
        if (QFileInfo(beside).absoluteFilePath() == info.absoluteFilePath())
            return fail(ReportTr::tr("%1: the runs would overwrite the report").arg(path));

    if (*format == ReportFormat::Html) {
        if (!reportSave(path, reportHtml(in).toUtf8(), error)) return {};
    } else {
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return fail(ReportTr::tr("Cannot write %1: %2").arg(path, file.errorString()));
        reportPrintPdf(in, &file);
        if (!file.commit())
            return fail(ReportTr::tr("Cannot write %1: %2").arg(path, file.errorString()));
    }
    if (!reportSave(csvPath, runsCsv(in), error)) return {};
    if (!reportSave(jsonPath, campaignJson(in), error)) return {};
    return {path, csvPath, jsonPath};
}

} // namespace gnss::qualify
