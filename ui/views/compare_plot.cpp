#include "views/compare_plot.h"

#include "models/compare_model.h"
#include "style/gnss_style.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace gnss::ui {

namespace {
constexpr std::int64_t kPlotDayMs = 86'400'000;
// At most this many points per series: a window of an hour at 10 Hz is thinned to it.
constexpr std::size_t kPlotMaxPoints = 2000;

// A round scale (1, 2, 5 × 10^n) at least `v`.
double niceCeil(double v) {
    if (v <= 0) return 1;
    const double e = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * e >= v) return m * e;
    return 10 * e;
}
} // namespace

ComparePlot::ComparePlot(const CompareModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("comparePlot");
    connect(model_, &CompareModel::changed, this, qOverload<>(&QWidget::update));
}

void ComparePlot::setReceiver(int receiver) {
    receiver_ = qMax(1, receiver);
    update();
}

void ComparePlot::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF all = rect().adjusted(4, 4, -4, -4);
    if (model_->receivers().size() <= receiver_) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(all, Qt::AlignCenter | Qt::TextWordWrap,
                   tr("Two or more receivers are compared here."));
        return;
    }
    // The fix strips take a thin row each; the plots the rest, however low the dock.
    const double fixRows = 14.0 * model_->receivers().size() + 6;
    const double side = std::min(all.width() * 0.45, all.height() - fixRows);
    paintScatter(p, QRectF(all.left(), all.top(), side, side));
    const QRectF right(all.left() + side + 12, all.top(), all.width() - side - 12, side);
    paintSeries(p, right);
    paintFixes(p, QRectF(all.left(), all.top() + side + 6, all.width(), fixRows - 6));
}

void ComparePlot::paintScatter(QPainter &p, const QRectF &r) {
    const auto &matches = model_->matches();
    const std::size_t pair = std::size_t(receiver_ - 1);
    const auto &report = model_->report();
    const double cep95 = pair < report.pairs.size() ? report.pairs[pair].cep95 : 0;
    const double cep50 = pair < report.pairs.size() ? report.pairs[pair].cep50 : 0;
    const double meanE = pair < report.pairs.size() ? report.pairs[pair].east.mean : 0;
    const double meanN = pair < report.pairs.size() ? report.pairs[pair].north.mean : 0;
    // The scale holds every point (a hard offset is what comparing is for).
    double extent = 0;
    for (const auto &m : matches)
        if (pair < m.differences.size() && m.differences[pair].horizontal)
            extent = std::max({extent, std::abs(*m.differences[pair].east),
                               std::abs(*m.differences[pair].north)});
    const double half = niceCeil(std::max(extent * 1.1, 0.05));
    const QPointF c = r.center();
    const double k = r.width() / (2 * half);
    p.setPen(palette().color(QPalette::Mid));
    p.drawRect(r);
    p.drawLine(QPointF(r.left(), c.y()), QPointF(r.right(), c.y()));
    p.drawLine(QPointF(c.x(), r.top()), QPointF(c.x(), r.bottom()));
    p.setPen(palette().color(QPalette::WindowText));
    if (r.width() > 100) // the scale, where it fits beside the points
        p.drawText(r.adjusted(4, 2, -4, -2), Qt::AlignTop | Qt::AlignLeft,
                   tr("N ↑  E →  ±%1 m").arg(half, 0, 'g', 3));
    const QColor colour = model_->receivers().value(receiver_).colour;
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    const std::size_t step = std::max<std::size_t>(1, matches.size() / kPlotMaxPoints);
    for (std::size_t i = 0; i < matches.size(); i += step) {
        const auto &d = matches[i].differences;
        if (pair >= d.size() || !d[pair].horizontal) continue;
        p.drawEllipse(QPointF(c.x() + *d[pair].east * k, c.y() - *d[pair].north * k), 2, 2);
    }
    // CEP circles about the mean difference.
    p.setBrush(Qt::NoBrush);
    const QPointF mean(c.x() + meanE * k, c.y() - meanN * k);
    for (const auto &[radius, dash] : {std::pair{cep50, Qt::SolidLine}, {cep95, Qt::DashLine}}) {
        if (radius <= 0) continue;
        p.setPen(QPen(palette().color(QPalette::WindowText), 1, dash));
        p.drawEllipse(mean, radius * k, radius * k);
    }
}

void ComparePlot::paintSeries(QPainter &p, const QRectF &r) {
    const auto &matches = model_->matches();
    const std::size_t pair = std::size_t(receiver_ - 1);
    p.setPen(palette().color(QPalette::Mid));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    if (matches.size() < 2) return;
    double lo = 0, hi = 0;
    for (const auto &m : matches) {
        if (pair >= m.differences.size()) continue;
        const auto &d = m.differences[pair];
        for (const auto &v : {d.horizontal, d.up})
            if (v) {
                lo = std::min(lo, *v);
                hi = std::max(hi, *v);
            }
    }
    hi = niceCeil(std::max(hi, 0.01));
    lo = lo < 0 ? -niceCeil(-lo) : 0;
    const std::int64_t t0 = matches.front().timeMs;
    const double span = double((matches.back().timeMs - t0 + kPlotDayMs) % kPlotDayMs) + 1;
    auto x = [&](std::int64_t t) {
        return r.left() + double((t - t0 + kPlotDayMs) % kPlotDayMs) / span * r.width();
    };
    auto y = [&](double v) { return r.bottom() - (v - lo) / (hi - lo) * r.height(); };
    p.drawLine(QPointF(r.left(), y(0)), QPointF(r.right(), y(0)));
    const std::size_t step = std::max<std::size_t>(1, matches.size() / kPlotMaxPoints);
    const QColor colour = model_->receivers().value(receiver_).colour;
    for (int which = 0; which < 2; ++which) {
        QPainterPath path;
        bool open = false;
        for (std::size_t i = 0; i < matches.size(); i += step) {
            if (pair >= matches[i].differences.size()) continue;
            const auto &d = matches[i].differences[pair];
            const auto v = which == 0 ? d.horizontal : d.up;
            if (!v) {
                open = false;
                continue;
            }
            const QPointF pt(x(matches[i].timeMs), y(*v));
            if (open)
                path.lineTo(pt);
            else
                path.moveTo(pt);
            open = true;
        }
        p.setPen(QPen(which == 0 ? colour : colour.darker(160), 1.5,
                      which == 0 ? Qt::SolidLine : Qt::DashLine));
        p.drawPath(path);
    }
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(
            r.adjusted(4, 2, -4, -2), Qt::AlignTop | Qt::AlignLeft,
            tr("horizontal (solid), up (dashed): %1 … %2 m").arg(lo, 0, 'g', 3).arg(hi, 0, 'g', 3));
}

void ComparePlot::paintFixes(QPainter &p, const QRectF &r) {
    const auto &matches = model_->matches();
    const auto &receivers = model_->receivers();
    if (matches.empty()) return;
    const std::int64_t t0 = matches.front().timeMs;
    const double span = double((matches.back().timeMs - t0 + kPlotDayMs) % kPlotDayMs) + 1;
    const double rowH = (r.height() - 4) / std::max<qsizetype>(1, receivers.size());
    const double labelW = std::min(160.0, r.width() * 0.3);
    p.setPen(Qt::NoPen);
    for (int i = 0; i < receivers.size(); ++i) {
        const QRectF row(r.left() + labelW, r.top() + i * rowH, r.width() - labelW, rowH - 2);
        // One rectangle per run of the same fix.
        auto at = [&](std::size_t k) {
            return k < matches.size()
                           ? double((matches[k].timeMs - t0 + kPlotDayMs) % kPlotDayMs) / span
                           : 1.0;
        };
        auto fixOf = [&](std::size_t k) {
            return std::size_t(i) < matches[k].fixes.size() ? matches[k].fixes[std::size_t(i)]
                                                            : FixType::None;
        };
        std::size_t start = 0;
        for (std::size_t k = 1; k <= matches.size(); ++k) {
            if (k < matches.size() && fixOf(k) == fixOf(start)) continue;
            const double a = at(start), b = at(k);
            p.fillRect(QRectF(row.left() + a * row.width(), row.top(),
                              std::max(1.0, (b - a) * row.width()), row.height()),
                       style::fixTypeColor(fixOf(start)));
            start = k;
        }
        p.setPen(receivers[i].colour);
        p.drawText(QRectF(r.left(), row.top(), labelW - 4, row.height()),
                   Qt::AlignVCenter | Qt::AlignLeft,
                   p.fontMetrics().elidedText(receivers[i].name, Qt::ElideRight, int(labelW - 4)));
        p.setPen(Qt::NoPen);
    }
}

} // namespace gnss::ui
