// The qualification's plots painted with QPainter: the CDF of the times to first fix (a step line
// per receiver's kind of start, with axes, grid and legend), the histogram of horizontal errors
// (with CEP50 and CEP95 marked), and the series a report's receivers give; the kinds of start
// named in the user's language.
#include "qualify/plots.h"

#include "compare/spread.h"
#include "core/dialect.h"
#include "qualify/report.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QRectF>

#include <algorithm>
#include <cmath>

namespace gnss::qualify {

namespace {

// The texts' context for translation, the report's (the plots are in it).
class PlotTr {
    Q_DECLARE_TR_FUNCTIONS(gnss::qualify::Report)
};

// The series' colours, in order: blue, orange, green, red, purple, brown, pink, grey.
constexpr QRgb kPlotPalette[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728,
                                 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f};

// The round step (1, 2 or 5 × 10^k) that splits `span` into about `parts` (no fewer).
double plotNiceStep(double span, int parts) {
    if (!(span > 0) || !std::isfinite(span)) return 1;
    const double raw = span / parts;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / magnitude;
    const double m = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
    return m * magnitude;
}

// `span` rounded up to a whole number of `step`s (at least one).
double plotRoundUp(double span, double step) {
    return std::max(1.0, std::ceil(span / step - 1e-9)) * step;
}

// A tick's value with as many decimals as its step needs.
QString plotTickText(double v, double step) {
    const int decimals = step >= 1 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(v, 'f', std::clamp(decimals, 0, 6));
}

// The painter's own font, sized to the area.
void plotSizeFont(QPainter &p, const QRectF &area) {
    QFont f = p.font();
    f.setPixelSize(std::max(9, int(area.height() / 28)));
    p.setFont(f);
}

struct PlotAxes {
    double xMax = 1, xStep = 1; // along, from 0
    double yMax = 100, yStep = 25;
    QString ySuffix; // after each y tick (" %")
    QString xTitle;  // under the x ticks
};

// The grid, the axes, their ticks and the x title in `area`; the rectangle left for the data
// (empty when the area is too small for it).
QRectF plotPaintAxes(QPainter &p, const QRectF &area, const PlotAxes &a, const QColor &text,
                     const QColor &grid) {
    const QFontMetricsF fm(p.font());
    const double lh = fm.height();
    const int xTicks = std::min(200, int(std::lround(a.xMax / a.xStep)));
    const int yTicks = std::min(200, int(std::lround(a.yMax / a.yStep)));
    double yLabelWidth = 0;
    for (int i = 0; i <= yTicks; ++i)
        yLabelWidth = std::max(
                yLabelWidth, fm.horizontalAdvance(plotTickText(i * a.yStep, a.yStep) + a.ySuffix));
    const double lastXLabel = fm.horizontalAdvance(plotTickText(a.xMax, a.xStep)) / 2;
    const QRectF plot = area.adjusted(yLabelWidth + lh * 0.8, lh * 0.8,
                                      -std::max(lh * 0.8, lastXLabel + 2), -(lh * 2.6));
    if (plot.width() < 10 || plot.height() < 10) return {};

    p.setBrush(Qt::NoBrush);
    QPen gridPen(grid, 1);
    gridPen.setCosmetic(true);
    for (int i = 0; i <= xTicks; ++i) {
        const double x = plot.left() + i * a.xStep / a.xMax * plot.width();
        p.setPen(gridPen);
        p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        p.setPen(text);
        p.drawText(QRectF(x - 60, plot.bottom() + lh * 0.25, 120, lh),
                   Qt::AlignHCenter | Qt::AlignTop, plotTickText(i * a.xStep, a.xStep));
    }
    for (int i = 0; i <= yTicks; ++i) {
        const double y = plot.bottom() - i * a.yStep / a.yMax * plot.height();
        p.setPen(gridPen);
        p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        p.setPen(text);
        p.drawText(QRectF(area.left(), y - lh / 2, yLabelWidth + lh * 0.4, lh),
                   Qt::AlignRight | Qt::AlignVCenter,
                   plotTickText(i * a.yStep, a.yStep) + a.ySuffix);
    }
    QPen axisPen(text, 1);
    axisPen.setCosmetic(true);
    p.setPen(axisPen);
    p.drawLine(plot.bottomLeft(), plot.bottomRight());
    p.drawLine(plot.bottomLeft(), plot.topLeft());
    p.drawText(QRectF(plot.left(), plot.bottom() + lh * 1.4, plot.width(), lh),
               Qt::AlignHCenter | Qt::AlignTop, a.xTitle);
    return plot;
}

void plotCentredText(QPainter &p, const QRectF &r, const QColor &text, const QString &s) {
    p.setPen(text);
    p.drawText(r, Qt::AlignCenter | Qt::TextWordWrap, s);
}

} // namespace

QString startName(ReceiverAction a) {
    switch (a) {
    case ReceiverAction::ColdStart: return PlotTr::tr("cold");
    case ReceiverAction::WarmStart: return PlotTr::tr("warm");
    case ReceiverAction::HotStart: return PlotTr::tr("hot");
    default: break;
    }
    return QString::fromUtf8(toString(a).data(), qsizetype(toString(a).size()));
}

std::vector<CdfSeries> cdfSeriesOf(const std::vector<ReportReceiver> &receivers) {
    std::vector<CdfSeries> out;
    const bool several = receivers.size() > 1;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
        for (ReceiverAction a :
             {ReceiverAction::ColdStart, ReceiverAction::WarmStart, ReceiverAction::HotStart}) {
            CdfSeries s;
            for (const TtffRun &r : receivers[i].runs)
                if (r.start == a && r.outcome == RunOutcome::Fixed && r.fix3d)
                    s.seconds.push_back(*r.fix3d);
            if (s.seconds.empty()) continue;
            s.label =
                    several ? QStringLiteral("#%1 %2").arg(i + 1).arg(startName(a)) : startName(a);
            s.colour = QColor::fromRgb(kPlotPalette[out.size() % std::size(kPlotPalette)]);
            out.push_back(std::move(s));
        }
    }
    return out;
}

void paintCdf(QPainter &p, const QRectF &area, const std::vector<CdfSeries> &series,
              const QColor &text, const QColor &grid) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    plotSizeFont(p, area);
    double latest = 0;
    bool any = false;
    for (const CdfSeries &s : series)
        for (double v : s.seconds)
            if (std::isfinite(v)) {
                latest = std::max(latest, v);
                any = true;
            }
    PlotAxes axes;
    const double span = any ? std::max(latest * 1.05, 1.0) : 60.0;
    axes.xStep = plotNiceStep(span, 8);
    axes.xMax = plotRoundUp(span, axes.xStep);
    axes.ySuffix = QStringLiteral("\u00a0%");
    axes.xTitle = PlotTr::tr("Time to first fix, s");
    const QRectF plot = plotPaintAxes(p, area, axes, text, grid);
    if (plot.isEmpty()) {
        p.restore();
        return;
    }
    if (!any) {
        plotCentredText(p, plot, text, PlotTr::tr("No run has fixed yet"));
        p.restore();
        return;
    }

    auto xOf = [&](double s) {
        return plot.left() + std::clamp(s / axes.xMax, 0.0, 1.0) * plot.width();
    };
    auto yOf = [&](double share) { return plot.bottom() - share * plot.height(); };
    const double width = std::max(2.0, area.height() / 160);
    p.setClipRect(plot.adjusted(-width, -width, width, width));
    p.setBrush(Qt::NoBrush);
    for (const CdfSeries &s : series) {
        std::vector<double> v;
        for (double x : s.seconds)
            if (std::isfinite(x)) v.push_back(x);
        if (v.empty()) continue;
        std::sort(v.begin(), v.end());
        const double n = double(v.size());
        QPainterPath path(QPointF(xOf(0), yOf(0)));
        for (std::size_t i = 0; i < v.size(); ++i) {
            path.lineTo(xOf(v[i]), yOf(double(i) / n));
            path.lineTo(xOf(v[i]), yOf(double(i + 1) / n));
        }
        path.lineTo(xOf(axes.xMax), yOf(1));
        p.setPen(QPen(s.colour, width, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin));
        p.drawPath(path);
    }
    p.setClipping(false);

    // The legend, top left inside the plot.
    const QFontMetricsF fm(p.font());
    const double lh = fm.height();
    double labelWidth = 0;
    for (const CdfSeries &s : series)
        labelWidth = std::max(labelWidth, fm.horizontalAdvance(s.label));
    const double swatch = lh * 1.2;
    const QRectF box(plot.left() + lh * 0.5, plot.top() + lh * 0.5, labelWidth + swatch + lh * 1.0,
                     lh * (double(series.size()) + 0.4));
    QPen boxPen(grid, 1);
    boxPen.setCosmetic(true);
    p.setPen(boxPen);
    p.setBrush(p.background());
    p.drawRect(box);
    for (std::size_t i = 0; i < series.size(); ++i) {
        const double y = box.top() + lh * (0.2 + double(i));
        p.fillRect(QRectF(box.left() + lh * 0.3, y + lh * 0.35, swatch, lh * 0.3),
                   series[i].colour);
        p.setPen(text);
        p.drawText(QRectF(box.left() + lh * 0.3 + swatch + lh * 0.3, y, labelWidth + lh, lh),
                   Qt::AlignLeft | Qt::AlignVCenter, series[i].label);
    }
    p.restore();
}

void paintHistogram(QPainter &p, const QRectF &area, const std::vector<double> &values,
                    const QString &unitSymbol, double perMetre, const QColor &bars,
                    const QColor &text, const QColor &grid, double cep50, double cep95) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    plotSizeFont(p, area);
    if (!(perMetre > 0) || !std::isfinite(perMetre)) perMetre = 1;
    std::vector<double> v;
    v.reserve(values.size());
    for (double x : values)
        if (std::isfinite(x)) v.push_back(std::abs(x) * perMetre);
    PlotAxes axes;
    axes.ySuffix = QStringLiteral("\u00a0%");
    axes.xTitle = PlotTr::tr("Horizontal error, %1").arg(unitSymbol);
    if (v.empty()) {
        axes.xMax = 1;
        axes.xStep = 0.2;
        const QRectF plot = plotPaintAxes(p, area, axes, text, grid);
        plotCentredText(p, plot.isEmpty() ? area : plot, text, PlotTr::tr("No positions"));
        p.restore();
        return;
    }
    std::sort(v.begin(), v.end());
    double top = compare::quantile(v, 0.99);
    if (!(top > 0)) top = v.back() > 0 ? v.back() : 1;
    const double binWidth = plotNiceStep(top, 20);
    const int bins = std::max(1, int(std::ceil(top / binWidth - 1e-9)));
    std::vector<double> share(std::size_t(bins), 0.0);
    for (double x : v) share[std::size_t(std::clamp(int(x / binWidth), 0, bins - 1))] += 1;
    double most = 0;
    for (double &s : share) {
        s = s * 100.0 / double(v.size());
        most = std::max(most, s);
    }
    const double c50 = cep50 > 0 ? cep50 * perMetre : 0, c95 = cep95 > 0 ? cep95 * perMetre : 0;
    const double span = std::max({bins * binWidth, c50 * 1.05, c95 * 1.05});
    axes.xStep = plotNiceStep(span, 8);
    axes.xMax = plotRoundUp(span, axes.xStep);
    axes.yStep = plotNiceStep(most, 5);
    axes.yMax = plotRoundUp(most, axes.yStep);
    const QRectF plot = plotPaintAxes(p, area, axes, text, grid);
    if (plot.isEmpty()) {
        p.restore();
        return;
    }
    auto xOf = [&](double x) {
        return plot.left() + std::clamp(x / axes.xMax, 0.0, 1.0) * plot.width();
    };
    for (int i = 0; i < bins; ++i) {
        if (share[std::size_t(i)] <= 0) continue;
        const double left = xOf(i * binWidth), right = xOf((i + 1) * binWidth);
        const double h = share[std::size_t(i)] / axes.yMax * plot.height();
        p.fillRect(QRectF(left + 0.5, plot.bottom() - h, std::max(1.0, right - left - 1.0), h),
                   bars);
    }
    const QFontMetricsF fm(p.font());
    QPen dashed(text, std::max(1.0, area.height() / 300), Qt::DashLine);
    int marked = 0;
    for (const auto &[radius, label] :
         {std::pair(c50, QStringLiteral("CEP50")), std::pair(c95, QStringLiteral("CEP95"))}) {
        if (!(radius > 0)) continue;
        const double x = xOf(radius);
        p.setPen(dashed);
        p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        p.setPen(text);
        const double y = plot.top() + fm.height() * (1.0 + marked++);
        const double w = fm.horizontalAdvance(label);
        // Beside the line, on its left when there is no room on the right.
        const double tx = x + 4 + w > plot.right() ? x - 4 - w : x + 4;
        p.drawText(QPointF(tx, y), label);
    }
    p.restore();
}

void paintErrorSeries(QPainter &p, const QRectF &area, const std::vector<double> &horizontal,
                      const std::vector<double> &vertical, const QString &unitSymbol,
                      double perMetre, const QColor &horizontalColour, const QColor &verticalColour,
                      const QColor &text, const QColor &grid) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    plotSizeFont(p, area);
    if (!(perMetre > 0) || !std::isfinite(perMetre)) perMetre = 1;
    double most = 0;
    bool anyVertical = false;
    for (double x : horizontal)
        if (std::isfinite(x)) most = std::max(most, std::abs(x) * perMetre);
    for (double x : vertical)
        if (std::isfinite(x)) {
            most = std::max(most, std::abs(x) * perMetre);
            anyVertical = true;
        }
    const std::size_t n = std::max(horizontal.size(), vertical.size());
    PlotAxes axes;
    axes.ySuffix = QChar(0x00a0) + unitSymbol;
    axes.xTitle = PlotTr::tr("Epoch");
    axes.xStep = plotNiceStep(std::max<double>(double(n), 1), 8);
    axes.xMax = plotRoundUp(std::max<double>(double(n), 1), axes.xStep);
    // Room above the largest error (the legend is there).
    const double span = most > 0 ? most * 1.15 : 1;
    axes.yStep = plotNiceStep(span, 5);
    axes.yMax = plotRoundUp(span, axes.yStep);
    const QRectF plot = plotPaintAxes(p, area, axes, text, grid);
    if (plot.isEmpty()) {
        p.restore();
        return;
    }
    if (n == 0) {
        plotCentredText(p, plot, text, PlotTr::tr("No positions"));
        p.restore();
        return;
    }
    const double width = std::max(1.5, area.height() / 250);
    p.setClipRect(plot);
    // Per pixel column the largest error of its epochs: a day of epochs stays a line.
    auto draw = [&](const std::vector<double> &values, const QColor &colour) {
        // Per column: kNone (no epoch there: the line goes on), kGap (epochs without a value:
        // the line breaks), else the largest value.
        constexpr double kNone = -1, kGap = -2;
        const int columns = std::max(1, int(plot.width()));
        std::vector<double> top(std::size_t(columns), kNone);
        for (std::size_t i = 0; i < values.size(); ++i) {
            const int c = std::clamp(int(double(i) / axes.xMax * columns), 0, columns - 1);
            double &t = top[std::size_t(c)];
            if (std::isfinite(values[i]))
                t = std::max(t, std::abs(values[i]) * perMetre);
            else if (t == kNone)
                t = kGap;
        }
        QPainterPath path;
        bool open = false;
        for (int c = 0; c < columns; ++c) {
            const double t = top[std::size_t(c)];
            if (t == kNone) continue;
            if (t == kGap) {
                open = false;
                continue;
            }
            const QPointF at(plot.left() + c + 0.5, plot.bottom() - t / axes.yMax * plot.height());
            if (open)
                path.lineTo(at);
            else
                path.moveTo(at);
            open = true;
        }
        p.setPen(QPen(colour, width));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    };
    draw(horizontal, horizontalColour);
    if (anyVertical) draw(vertical, verticalColour);
    p.setClipping(false);
    // The legend, top right inside the plot.
    const QFontMetricsF fm(p.font());
    const double lh = fm.height();
    double x = plot.right() - lh * 0.5;
    const std::pair<QString, QColor> keys[] = {
            {PlotTr::tr("horizontal"), horizontalColour},
            {PlotTr::tr("vertical"), verticalColour},
    };
    for (int k = anyVertical ? 1 : 0; k >= 0; --k) {
        const double w = fm.horizontalAdvance(keys[k].first);
        x -= w;
        p.setPen(text);
        p.drawText(QPointF(x, plot.top() + lh), keys[k].first);
        x -= lh * 1.4;
        p.fillRect(QRectF(x, plot.top() + lh * 0.55, lh, lh * 0.3), keys[k].second);
        x -= lh * 0.8;
    }
    p.restore();
}

} // namespace gnss::qualify
