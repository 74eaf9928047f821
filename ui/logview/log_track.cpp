#include "logview/log_track.h"

#include "logview/range_stats.h"
#include "style/gnss_style.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

namespace gnss::ui {

namespace {
constexpr double kPickRadius = 12; // pixels: how near a click must be to an epoch
constexpr double kFitMargin = 0.9; // the fitted track fills 90 % of the smaller side

// 1, 2 or 5 × 10^k metres, close to `metres`.
double roundLength(double metres) {
    const double mag = std::pow(10.0, std::floor(std::log10(metres)));
    const double n = metres / mag;
    return (n < 2 ? 1 : n < 5 ? 2 : 5) * mag;
}
} // namespace

LogTrack::LogTrack(LogCursor *cursor, QWidget *parent) : QWidget(parent), cursor_(cursor) {
    setObjectName("logTrack");
    connect(cursor_, &LogCursor::indexChanged, this, &LogTrack::reload);
    connect(cursor_, &LogCursor::moved, this, qOverload<>(&QWidget::update));
}

void LogTrack::setReference(std::optional<std::pair<double, double>> latLon) {
    reference_ = latLon;
    userView_ = false;
    reload();
}

void LogTrack::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    update();
}

void LogTrack::reload() {
    en_.clear();
    fix_.clear();
    const logview::LogView *log = cursor_->log();
    if (log && !cursor_->empty()) {
        log->withRecords([&](std::span<const logview::EpochRecord> recs) {
            // The mean about the first position (as the range statistics take it).
            double sLat = 0, sLon = 0, lat0 = NAN, lon0 = NAN;
            std::size_t n = 0;
            for (const auto &r : recs) {
                if (!r.hasPosition()) continue;
                if (n == 0) lat0 = r.lat, lon0 = r.lon;
                sLat += r.lat - lat0;
                sLon += r.lon - lon0;
                ++n;
            }
            origin_ = reference_ ? *reference_
                      : n        ? std::pair{lat0 + sLat / double(n), lon0 + sLon / double(n)}
                                 : std::pair{0.0, 0.0};
            const logview::LocalFrame frame(origin_.first, origin_.second);
            en_.reserve(recs.size());
            fix_.reserve(recs.size());
            for (const auto &r : recs) {
                if (r.hasPosition()) {
                    const auto [e, nn] = frame.toEastNorth(r.lat, r.lon);
                    en_.emplace_back(e, nn);
                } else {
                    en_.emplace_back(NAN, NAN);
                }
                fix_.push_back(r.fix);
            }
        });
    }
    if (!userView_) fit();
    dotsValid_ = false;
    update();
}

void LogTrack::fit() {
    double minE = INFINITY, maxE = -INFINITY, minN = INFINITY, maxN = -INFINITY;
    for (const QPointF &p : en_) {
        if (std::isnan(p.x())) continue;
        minE = std::min(minE, p.x()), maxE = std::max(maxE, p.x());
        minN = std::min(minN, p.y()), maxN = std::max(maxN, p.y());
    }
    if (!(minE <= maxE)) {
        centre_ = {};
        scale_ = 1;
    } else {
        centre_ = {(minE + maxE) / 2, (minN + maxN) / 2};
        const double span = std::max({maxE - minE, maxN - minN, 0.05});
        scale_ = kFitMargin * std::min(width(), height()) / span;
    }
    userView_ = false;
    dotsValid_ = false;
    update();
}

std::optional<QPointF> LogTrack::enOf(std::size_t k) const {
    if (k >= en_.size() || std::isnan(en_[k].x())) return std::nullopt;
    return en_[k];
}

QPointF LogTrack::toPixel(QPointF en) const {
    return {width() / 2.0 + (en.x() - centre_.x()) * scale_,
            height() / 2.0 - (en.y() - centre_.y()) * scale_};
}

QPointF LogTrack::toMetres(QPointF px) const {
    return {centre_.x() + (px.x() - width() / 2.0) / scale_,
            centre_.y() - (px.y() - height() / 2.0) / scale_};
}

std::optional<std::size_t> LogTrack::epochNear(QPointF pixel, double radius) const {
    std::optional<std::size_t> best;
    double bestD = radius * radius;
    for (std::size_t k = 0; k < en_.size(); ++k) {
        if (std::isnan(en_[k].x())) continue;
        const QPointF d = toPixel(en_[k]) - pixel;
        const double d2 = d.x() * d.x() + d.y() * d.y();
        if (d2 <= bestD) bestD = d2, best = k;
    }
    return best;
}

void LogTrack::renderDots() {
    const qreal dpr = devicePixelRatioF();
    dots_ = QImage(size() * dpr, QImage::Format_ARGB32_Premultiplied);
    dots_.setDevicePixelRatio(dpr);
    dots_.fill(Qt::transparent);
    QPainter p(&dots_);
    p.setRenderHint(QPainter::Antialiasing);
    // One dot per pixel and fix type: a day at 10 Hz standing still is a few hundred dots.
    const int w = width(), h = height();
    std::vector<quint8> seen(std::size_t(std::max(0, w * h)), 0);
    std::array<QVector<QPointF>, 9> byFix;
    for (std::size_t k = 0; k < en_.size(); ++k) {
        if (std::isnan(en_[k].x())) continue;
        const QPointF px = toPixel(en_[k]);
        const int x = int(px.x()), y = int(px.y());
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        quint8 &s = seen[std::size_t(y) * std::size_t(w) + std::size_t(x)];
        const quint8 f = std::min<quint8>(fix_[k], 8);
        if (s == f + 1) continue;
        s = quint8(f + 1);
        byFix[f].push_back(px);
    }
    for (std::size_t f = 0; f < byFix.size(); ++f) {
        if (byFix[f].isEmpty()) continue;
        p.setPen(
                QPen(style::fixTypeColor(static_cast<FixType>(f)), 3, Qt::SolidLine, Qt::RoundCap));
        p.drawPoints(byFix[f].constData(), int(byFix[f].size()));
    }
    dotsValid_ = true;
}

void LogTrack::paintEvent(QPaintEvent *) {
    QPainter p(this);
    const QPalette &pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    if (en_.empty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter,
                   cursor_->log() && cursor_->empty() ? tr("Indexing…") : tr("No positions"));
        return;
    }
    // The origin's cross.
    const QPointF o = toPixel({0, 0});
    QColor axis = pal.color(QPalette::Mid);
    p.setPen(axis);
    p.drawLine(QPointF(0, o.y()), QPointF(width(), o.y()));
    p.drawLine(QPointF(o.x(), 0), QPointF(o.x(), height()));
    if (!dotsValid_ || dots_.size() != size() * devicePixelRatioF()) renderDots();
    p.drawImage(0, 0, dots_);
    // Scale bar (in the user's units) and the origin.
    const double factor = fmt::lengthFactor(prefs_.units);
    const double barUnits = roundLength(std::max(1e-3, 80 / scale_ * factor));
    const double barPx = barUnits / factor * scale_;
    p.setPen(QPen(pal.color(QPalette::Text), 2));
    const QPointF b0(10, height() - 12);
    p.drawLine(b0, b0 + QPointF(barPx, 0));
    p.drawText(QPointF(b0.x(), b0.y() - 5),
               tr("%1 %2").arg(barUnits, 0, 'g', 3).arg(fmt::lengthUnit(prefs_.units)));
    p.drawText(rect().adjusted(6, 4, -6, -4), Qt::AlignTop | Qt::AlignLeft,
               tr("Origin %1, %2%3")
                       .arg(fmt::latitude(origin_.first, prefs_.coordinates),
                            fmt::longitude(origin_.second, prefs_.coordinates),
                            reference_ ? tr(" (reference)") : tr(" (mean)")));
    if (const auto c = enOf(cursor_->current())) {
        const QPointF px = toPixel(*c);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(pal.color(QPalette::WindowText), 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(px, 7, 7);
        p.drawLine(px - QPointF(11, 0), px - QPointF(4, 0));
        p.drawLine(px + QPointF(4, 0), px + QPointF(11, 0));
    }
}

void LogTrack::resizeEvent(QResizeEvent *) {
    if (!userView_) fit();
    dotsValid_ = false;
}

void LogTrack::wheelEvent(QWheelEvent *e) {
    const QPointF at = toMetres(e->position());
    const double f = e->angleDelta().y() > 0 ? 1.25 : 0.8;
    scale_ *= f;
    // Keep the point under the mouse where it is.
    centre_ = at - (at - centre_) / f;
    userView_ = true;
    dotsValid_ = false;
    update();
    e->accept();
}

void LogTrack::mousePressEvent(QMouseEvent *e) {
    if (press_.press(e)) pressCentre_ = centre_;
}

void LogTrack::mouseMoveEvent(QMouseEvent *e) {
    const auto d = press_.drag(e, false);
    if (!d) return;
    centre_ = pressCentre_ + QPointF(-d->x() / scale_, d->y() / scale_);
    userView_ = true;
    dotsValid_ = false;
    update();
}

void LogTrack::mouseReleaseEvent(QMouseEvent *e) {
    if (press_.release())
        if (const auto k = epochNear(e->position(), kPickRadius)) cursor_->seek(*k);
}

void LogTrack::mouseDoubleClickEvent(QMouseEvent *) {
    fit();
}

} // namespace gnss::ui
