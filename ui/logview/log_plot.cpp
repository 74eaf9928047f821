#include "logview/log_plot.h"

#include "style/gnss_style.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>
#include <limits>
#include <vector>

namespace gnss::ui {

namespace {
constexpr int kLeft = 58, kRight = 10, kTop = 8, kBottom = 22; // plot margins, pixels

// 1, 2 or 5 times a power of ten, about range/ticks.
double niceStep(double range, int ticks) {
    if (!(range > 0)) return 1;
    const double raw = range / ticks, mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double n = raw / mag;
    return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * mag;
}

QString shortTime(const logview::EpochRecord &r) {
    QString t = QString::fromStdString(logview::formatTime(r));
    // "2024-03-15T10:00:00.100Z" → "10:00:00"; "10:00:00.100" stays a time of day.
    if (const int T = int(t.indexOf(QLatin1Char('T'))); T >= 0) t = t.mid(T + 1);
    return t.left(8);
}
} // namespace

LogPlot::LogPlot(LogCursor *cursor, QWidget *parent) : QWidget(parent), cursor_(cursor) {
    setObjectName("logPlot");
    setMouseTracking(false);
    connect(cursor_, &LogCursor::indexChanged, this, [this] {
        if (!zoomed_)
            showAll();
        else
            invalidate();
    });
    connect(cursor_, &LogCursor::moved, this, &LogPlot::keepCursorInView);
    connect(cursor_, &LogCursor::rangeChanged, this, qOverload<>(&QWidget::update));
}

QString LogPlot::quantityName(Quantity q) {
    switch (q) {
    case Quantity::Altitude: return tr("Altitude");
    case Quantity::Speed: return tr("Speed");
    case Quantity::Satellites: return tr("Satellites used");
    case Quantity::Hdop: return tr("HDOP");
    case Quantity::Snr: return tr("Mean SNR");
    }
    return {};
}

void LogPlot::setQuantity(Quantity q) {
    quantity_ = q;
    invalidate();
}

void LogPlot::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    invalidate();
}

double LogPlot::value(const logview::EpochRecord &r) const {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    switch (quantity_) {
    case Quantity::Altitude:
        return r.hasPosition() ? double(r.altMsl) * fmt::lengthFactor(prefs_.units) : nan;
    case Quantity::Speed: return double(r.speed) * fmt::speedFactor(prefs_.units);
    case Quantity::Satellites: return r.sats == 255 ? nan : double(r.sats);
    case Quantity::Hdop: return double(r.hdop);
    case Quantity::Snr: return r.snr == 255 ? nan : double(r.snr);
    }
    return nan;
}

QString LogPlot::unit() const {
    switch (quantity_) {
    case Quantity::Altitude: return fmt::lengthUnit(prefs_.units);
    case Quantity::Speed: return fmt::speedUnit(prefs_.units);
    case Quantity::Snr: return tr("dB-Hz");
    default: return {};
    }
}

void LogPlot::showAll() {
    zoomed_ = false;
    first_ = 0;
    last_ = cursor_->epochCount() > 1 ? double(cursor_->epochCount() - 1) : 1;
    invalidate();
}

void LogPlot::setWindow(double first, double last) {
    const double n = cursor_->epochCount() > 1 ? double(cursor_->epochCount() - 1) : 1;
    const double span = std::clamp(last - first, 4.0, n);
    first = std::clamp(first, 0.0, n - span);
    first_ = first;
    last_ = first + span;
    zoomed_ = span < n;
    invalidate();
}

QRect LogPlot::plotRect() const {
    return rect().adjusted(kLeft, kTop, -kRight, -kBottom);
}

double LogPlot::xOfEpoch(double epoch) const {
    const QRect r = plotRect();
    return r.left() + (epoch - first_) / std::max(1e-9, last_ - first_) * (r.width() - 1);
}

double LogPlot::epochAtX(double x) const {
    const QRect r = plotRect();
    return first_ + (x - r.left()) / std::max(1, r.width() - 1) * (last_ - first_);
}

void LogPlot::keepCursorInView(std::size_t epoch) {
    if (zoomed_ && (double(epoch) < first_ || double(epoch) > last_)) {
        const double span = last_ - first_;
        setWindow(double(epoch) - span / 2, double(epoch) + span / 2);
    } else {
        update();
    }
}

void LogPlot::invalidate() {
    imageValid_ = false;
    update();
}

void LogPlot::paintEvent(QPaintEvent *) {
    const qreal dpr = devicePixelRatioF();
    if (!imageValid_ || image_.size() != size() * dpr) {
        image_ = QImage(size() * dpr, QImage::Format_ARGB32_Premultiplied);
        image_.setDevicePixelRatio(dpr);
        QPainter ip(&image_);
        renderSeries(ip);
        imageValid_ = true;
    }
    QPainter p(this);
    p.drawImage(0, 0, image_);
    const QPalette &pal = palette();
    const QRect r = plotRect();
    if (cursor_->empty()) return;
    if (cursor_->hasRange()) {
        const auto [s, e] = cursor_->selection();
        QColor shade = pal.color(QPalette::Highlight);
        shade.setAlpha(50);
        const double x0 = std::max<double>(r.left(), xOfEpoch(double(s)));
        const double x1 = std::min<double>(r.right(), xOfEpoch(double(e)));
        if (x1 >= x0) p.fillRect(QRectF(x0, r.top(), std::max(1.0, x1 - x0), r.height()), shade);
    }
    const double cx = xOfEpoch(double(cursor_->current()));
    if (cx >= r.left() && cx <= r.right()) {
        p.setPen(QPen(pal.color(QPalette::WindowText), 1.5, Qt::DashLine));
        p.drawLine(QPointF(cx, r.top()), QPointF(cx, r.bottom()));
    }
}

// Everything but the cursor and the range: redrawn only when the view or the data changes.
void LogPlot::renderSeries(QPainter &p) {
    const QPalette &pal = palette();
    const QRect r = plotRect();
    p.fillRect(rect(), pal.color(QPalette::Base));
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(r.adjusted(0, 0, -1, -1));
    const logview::LogView *log = cursor_->log();
    const std::size_t n = cursor_->epochCount();
    if (!log || n == 0 || r.width() < 10 || r.height() < 10) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(r, Qt::AlignCenter, log ? tr("Indexing…") : tr("No log open"));
        return;
    }
    struct Column {
        double lo = INFINITY, hi = -INFINITY, first = NAN, last = NAN;
        quint8 fix = 0;
        bool gap = false;
    };
    std::vector<Column> cols(std::size_t(r.width()));
    const auto a = std::size_t(std::max(0.0, std::floor(first_)));
    const auto b = std::min(n - 1, std::size_t(std::ceil(last_)));
    double lo = INFINITY, hi = -INFINITY;
    std::vector<std::size_t> times; // epochs for the x labels
    log->withRecords([&](std::span<const logview::EpochRecord> recs) {
        for (std::size_t i = a; i <= b && i < recs.size(); ++i) {
            const double v = value(recs[i]);
            const int c = int(xOfEpoch(double(i))) - r.left();
            if (c < 0 || c >= int(cols.size())) continue;
            Column &col = cols[std::size_t(c)];
            if (recs[i].flags & (logview::kGapBefore | logview::kTimeBack)) col.gap = true;
            if (std::isnan(v)) continue;
            col.lo = std::min(col.lo, v);
            col.hi = std::max(col.hi, v);
            if (std::isnan(col.first)) col.first = v;
            col.last = v;
            col.fix = recs[i].fix;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        for (int k = 0; k <= 4; ++k) {
            const auto e = std::size_t(
                    std::clamp(first_ + (last_ - first_) * k / 4.0, 0.0, double(recs.size() - 1)));
            if (e < recs.size() && recs[e].hasTime()) {
                const double x = xOfEpoch(double(e));
                p.setPen(pal.color(QPalette::Text));
                const QString t = shortTime(recs[e]);
                const int w = p.fontMetrics().horizontalAdvance(t);
                p.drawText(QPointF(std::clamp(x - w / 2.0, 0.0, double(width() - w)), height() - 6),
                           t);
            }
        }
    });
    if (!(lo <= hi)) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(r, Qt::AlignCenter, tr("The log has no %1").arg(quantityName(quantity_)));
    } else {
        if (hi - lo < 1e-6) {
            lo -= 0.5;
            hi += 0.5;
        }
        const double pad = (hi - lo) * 0.05;
        lo -= pad;
        hi += pad;
        auto y = [&](double v) { return r.bottom() - (v - lo) / (hi - lo) * (r.height() - 1); };
        // Grid and y labels.
        const double step = niceStep(hi - lo, std::max(2, r.height() / 30));
        QColor grid = pal.color(QPalette::Mid);
        grid.setAlpha(90);
        const int decimals = step < 1 ? int(std::ceil(-std::log10(step))) : 0;
        for (double v = std::ceil(lo / step) * step; v <= hi; v += step) {
            p.setPen(grid);
            p.drawLine(QPointF(r.left(), y(v)), QPointF(r.right(), y(v)));
            p.setPen(pal.color(QPalette::Text));
            p.drawText(QRectF(0, y(v) - 8, kLeft - 4, 16), Qt::AlignRight | Qt::AlignVCenter,
                       QString::number(v, 'f', decimals));
        }
        // The series: per column its range, joined to the previous column's last value.
        const Column *prev = nullptr;
        int prevX = 0;
        for (std::size_t c = 0; c < cols.size(); ++c) {
            const Column &col = cols[c];
            if (std::isnan(col.first)) {
                if (col.gap) prev = nullptr;
                continue;
            }
            const int x = r.left() + int(c);
            p.setPen(QPen(style::fixTypeColor(static_cast<FixType>(col.fix)), 1.5));
            if (prev && !col.gap)
                p.drawLine(QPointF(prevX, y(prev->last)), QPointF(x, y(col.first)));
            p.drawLine(QPointF(x, y(col.lo)), QPointF(x, y(col.hi)));
            prev = &col;
            prevX = x;
        }
    }
    p.setPen(pal.color(QPalette::Text));
    const QString title = unit().isEmpty() ? quantityName(quantity_)
                                           : tr("%1, %2").arg(quantityName(quantity_), unit());
    p.drawText(r.adjusted(6, 2, -6, 0), Qt::AlignTop | Qt::AlignRight, title);
}

void LogPlot::wheelEvent(QWheelEvent *e) {
    if (cursor_->empty()) return;
    const double at = epochAtX(e->position().x());
    const double f = e->angleDelta().y() > 0 ? 0.8 : 1.25;
    setWindow(at - (at - first_) * f, at + (last_ - at) * f);
    e->accept();
}

void LogPlot::mousePressEvent(QMouseEvent *e) {
    if (!press_.press(e)) return;
    pressFirst_ = first_;
    pressLast_ = last_;
}

void LogPlot::mouseMoveEvent(QMouseEvent *e) {
    const auto d = press_.drag(e, true);
    if (!d) return;
    const double dx = d->x();
    const double perPixel = (pressLast_ - pressFirst_) / std::max(1, plotRect().width() - 1);
    setWindow(pressFirst_ - dx * perPixel, pressLast_ - dx * perPixel);
}

void LogPlot::mouseReleaseEvent(QMouseEvent *e) {
    if (press_.release() && !cursor_->empty())
        cursor_->seek(std::size_t(std::max(0.0, std::round(epochAtX(e->position().x())))));
}

void LogPlot::mouseDoubleClickEvent(QMouseEvent *) {
    showAll();
}

void LogPlot::changeEvent(QEvent *e) {
    if (e->type() == QEvent::PaletteChange || e->type() == QEvent::FontChange) invalidate();
    QWidget::changeEvent(e);
}

} // namespace gnss::ui
