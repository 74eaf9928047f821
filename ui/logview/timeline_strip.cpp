#include "logview/timeline_strip.h"

#include "style/gnss_style.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <array>

namespace gnss::ui {

namespace {
constexpr int kMargin = 6; // pixels left and right of the strip
} // namespace

TimelineStrip::TimelineStrip(LogCursor *cursor, QWidget *parent)
    : QWidget(parent), cursor_(cursor) {
    setObjectName("timelineStrip");
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setMinimumHeight(28);
    setFocusPolicy(Qt::ClickFocus);
    connect(cursor_, &LogCursor::indexChanged, this, &TimelineStrip::rebuild);
    connect(cursor_, &LogCursor::moved, this, qOverload<>(&QWidget::update));
    connect(cursor_, &LogCursor::rangeChanged, this, qOverload<>(&QWidget::update));
}

void TimelineStrip::setProgress(double fraction, const QString &text) {
    progress_ = fraction;
    progressText_ = text;
    update();
}

QRect TimelineStrip::stripRect() const {
    return rect().adjusted(kMargin, 4, -kMargin, -4);
}

int TimelineStrip::xOfEpoch(std::size_t epoch) const {
    const QRect r = stripRect();
    const std::size_t n = cursor_->epochCount();
    if (n <= 1) return r.left();
    return r.left() + int(double(epoch) / double(n - 1) * (r.width() - 1) + 0.5);
}

std::size_t TimelineStrip::epochAtX(int x) const {
    const QRect r = stripRect();
    const std::size_t n = cursor_->epochCount();
    if (n == 0) return 0;
    const double f = std::clamp(double(x - r.left()) / std::max(1, r.width() - 1), 0.0, 1.0);
    return std::min(n - 1, std::size_t(f * double(n - 1) + 0.5));
}

void TimelineStrip::resizeEvent(QResizeEvent *) {
    rebuild();
}

void TimelineStrip::rebuild() {
    bins_.assign(std::size_t(std::max(1, stripRect().width())), Bin{});
    const logview::LogView *log = cursor_->log();
    const std::size_t n = cursor_->epochCount();
    if (log && n) {
        const double perBin = double(bins_.size()) / double(n);
        std::vector<std::array<std::uint32_t, 9>> counts(bins_.size());
        log->withRecords([&](std::span<const logview::EpochRecord> recs) {
            const std::size_t m = std::min(n, recs.size());
            for (std::size_t i = 0; i < m; ++i) {
                const auto b = std::min(bins_.size() - 1, std::size_t(double(i) * perBin));
                const logview::EpochRecord &r = recs[i];
                ++counts[b][std::min<std::size_t>(r.fix, 8)];
                Bin &bin = bins_[b];
                bin.any = true;
                if (r.flags & (logview::kGapBefore | logview::kLinkGap | logview::kTimeBack))
                    bin.gap = true;
                if (r.flags & (logview::kChecksumErrors | logview::kDecodeErrors | logview::kJunk))
                    bin.errors = true;
            }
        });
        // A log shorter than the strip is wide: each epoch colours the columns up to the next.
        const std::size_t nb = bins_.size();
        for (std::size_t b = 0; b < nb; ++b) {
            const auto &c = counts[b];
            if (bins_[b].any) {
                bins_[b].fix = quint8(std::max_element(c.begin(), c.end()) - c.begin());
            } else if (b > 0 && bins_[b - 1].any) {
                bins_[b].any = true;
                bins_[b].fix = bins_[b - 1].fix;
                bins_[b].fill = true;
            }
        }
        for (const logview::LogEvent &e : log->events()) {
            if (e.kind == logview::EventKind::ChecksumErrors || e.kind == logview::EventKind::Gap)
                continue; // drawn as ticks of their own
            bins_[std::min(bins_.size() - 1, std::size_t(double(e.epoch) * perBin))].event = true;
        }
    }
    update();
}

void TimelineStrip::paintEvent(QPaintEvent *) {
    QPainter p(this);
    const QRect r = stripRect();
    const QPalette &pal = palette();
    p.fillRect(r, pal.color(QPalette::Base));
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(r.adjusted(0, 0, -1, -1));
    if (progress_ >= 0 && cursor_->empty()) {
        QRect done = r.adjusted(1, 1, -1, -1);
        done.setWidth(int(done.width() * std::clamp(progress_, 0.0, 1.0)));
        p.fillRect(done, pal.color(QPalette::Highlight).lighter(130));
        p.setPen(pal.color(QPalette::Text));
        p.drawText(r, Qt::AlignCenter, progressText_);
        return;
    }
    const int top = r.top() + 6, bottom = r.bottom() - 5;
    for (std::size_t b = 0; b < bins_.size(); ++b) {
        const Bin &bin = bins_[b];
        if (!bin.any) continue;
        const int x = r.left() + int(b);
        p.setPen(style::fixTypeColor(static_cast<FixType>(bin.fix)));
        p.drawLine(x, top, x, bottom);
    }
    // Ticks: gaps above (the text colour), errors below (red), events on top (highlight).
    for (std::size_t b = 0; b < bins_.size(); ++b) {
        const Bin &bin = bins_[b];
        const int x = r.left() + int(b);
        if (bin.fill) continue;
        if (bin.gap) {
            p.setPen(pal.color(QPalette::WindowText));
            p.drawLine(x, r.top() + 1, x, top + 3);
        }
        if (bin.errors) {
            p.setPen(style::errorColor());
            p.drawLine(x, bottom - 3, x, r.bottom() - 1);
        }
        if (bin.event) {
            p.setPen(pal.color(QPalette::Highlight));
            p.drawLine(x, r.top() + 1, x, r.top() + 4);
        }
    }
    if (cursor_->empty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(r, Qt::AlignCenter,
                   !progressText_.isEmpty() ? progressText_ : tr("Open a log (File → Open Log…)"));
        return;
    }
    if (cursor_->hasRange()) {
        const auto [a, b] = cursor_->selection();
        QColor shade = pal.color(QPalette::Highlight);
        shade.setAlpha(70);
        p.fillRect(QRect(QPoint(xOfEpoch(a), r.top()), QPoint(xOfEpoch(b), r.bottom())), shade);
    }
    const int cx = xOfEpoch(cursor_->current());
    p.setPen(QPen(pal.color(QPalette::WindowText), 2));
    p.drawLine(cx, rect().top(), cx, rect().bottom());
}

void TimelineStrip::mousePressEvent(QMouseEvent *e) {
    if (e->button() != Qt::LeftButton || cursor_->empty()) return;
    const std::size_t k = epochAtX(int(e->position().x()));
    if (e->modifiers() & Qt::ShiftModifier) {
        selecting_ = true;
        selectFrom_ = k;
        cursor_->setRange(k, k);
    } else {
        dragging_ = true;
        cursor_->seek(k);
    }
}

void TimelineStrip::mouseMoveEvent(QMouseEvent *e) {
    const std::size_t k = epochAtX(int(e->position().x()));
    if (selecting_)
        cursor_->setRange(selectFrom_, k);
    else if (dragging_)
        cursor_->seek(k);
}

void TimelineStrip::mouseReleaseEvent(QMouseEvent *) {
    selecting_ = dragging_ = false;
}

bool TimelineStrip::event(QEvent *e) {
    if (e->type() == QEvent::ToolTip && cursor_->log() && !cursor_->empty()) {
        auto *h = static_cast<QHelpEvent *>(e);
        const std::size_t k = epochAtX(h->pos().x());
        if (const auto r = cursor_->log()->epoch(k)) {
            QToolTip::showText(h->globalPos(),
                               tr("#%1 · %2 · %3")
                                       .arg(k)
                                       .arg(QString::fromStdString(logview::formatTime(*r)))
                                       .arg(style::fixTypeLabel(r->fixType())),
                               this);
            return true;
        }
    }
    return QWidget::event(e);
}

} // namespace gnss::ui
