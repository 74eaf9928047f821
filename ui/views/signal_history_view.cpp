#include "views/signal_history_view.h"

#include "models/signal_history_model.h"
#include "style/gnss_style.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

#include <cmath>

namespace gnss::ui {

namespace {
constexpr double kHistoryLowCn0 = 10, kHistoryHighCn0 = 60;

QString labelOf(SatelliteRef s) {
    return QString::fromStdString(satelliteLabel(s));
}
} // namespace

class SignalHistoryView::Canvas : public QWidget {
public:
    Canvas(SignalHistoryModel *model, QWidget *parent) : QWidget(parent), model_(model) {
        setObjectName("signalHistoryCanvas");
        setMinimumSize(200, 60);
    }
    std::set<QString> chosen;
    bool live = true;
    std::function<void(const QString &)> onPick;

protected:
    QRectF plotRect() const { return QRectF(rect()).adjusted(36, 8, -8, -20); }

    void paintEvent(QPaintEvent *) override {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        const QRectF r = plotRect();
        const SignalHistory &h = model_->history();
        const QColor text = palette().color(QPalette::WindowText);
        p.setPen(palette().color(QPalette::Mid));
        p.drawRect(r);
        for (double v = kHistoryLowCn0; v <= kHistoryHighCn0; v += 10) {
            const double y = yOf(v, r);
            p.setPen(QPen(palette().color(QPalette::Midlight), 1, Qt::DotLine));
            p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
            p.setPen(text);
            p.drawText(QRectF(0, y - 8, r.left() - 4, 16), Qt::AlignRight | Qt::AlignVCenter,
                       QString::number(int(v)));
        }
        if (h.series().empty()) {
            p.setPen(palette().color(QPalette::PlaceholderText));
            p.drawText(r, Qt::AlignCenter, tr("No C/N0 yet"));
            return;
        }
        // The time axis ends with the newest sample kept (the step in progress is not one yet).
        t0_ = h.oldestMs();
        std::int64_t newest = t0_;
        for (const auto &[key, samples] : h.series())
            if (!samples.empty()) newest = std::max(newest, samples.back().timeMs);
        t1_ = std::max(newest, t0_ + 1000);
        // The time axis: minutes before the newest sample.
        p.setPen(text);
        p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), 16), Qt::AlignLeft,
                   tr("−%1 min").arg(double(t1_ - t0_) / 60'000.0, 0, 'f', 1));
        // Live, the right edge is now; a log's history ends with the log.
        p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), 16), Qt::AlignRight,
                   live ? tr("now") : tr("end"));
        p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), 16), Qt::AlignHCenter,
                   tr("C/N0 (dB-Hz) of each signal"));
        // The faint ones first, the chosen on top.
        for (int pass = 0; pass < 2; ++pass) {
            for (const auto &[key, samples] : h.series()) {
                const QString label = labelOf(key.sat);
                const bool bold = chosen.count(label) > 0;
                if ((pass == 1) != bold || samples.empty()) continue;
                QColor c = style::constellationColor(key.sat.system);
                if (!chosen.empty() && !bold) c.setAlpha(70);
                QPainterPath path;
                std::int64_t last = -1;
                for (const auto &s : samples) {
                    const QPointF pt(xOf(s.timeMs, r), yOf(s.cn0, r));
                    // A gap longer than a few steps is not bridged.
                    if (last < 0 || s.timeMs - last > 5 * stepOf(samples))
                        path.moveTo(pt);
                    else
                        path.lineTo(pt);
                    last = s.timeMs;
                }
                p.setPen(QPen(c, bold ? 2.5 : 1));
                p.drawPath(path);
                if (bold) {
                    const auto &s = samples.back();
                    p.setPen(c);
                    p.drawText(QPointF(xOf(s.timeMs, r) - 28, yOf(s.cn0, r) - 4),
                               key.signalId ? tr("%1/%2").arg(label).arg(key.signalId) : label);
                }
            }
        }
    }

    void mousePressEvent(QMouseEvent *e) override {
        // The line nearest the click (within 8 px) is chosen, or no longer chosen.
        const QRectF r = plotRect();
        double best = 8;
        QString pick;
        for (const auto &[key, samples] : model_->history().series())
            for (const auto &s : samples) {
                const double d = std::hypot(xOf(s.timeMs, r) - e->position().x(),
                                            yOf(s.cn0, r) - e->position().y());
                if (d < best) {
                    best = d;
                    pick = labelOf(key.sat);
                }
            }
        if (!pick.isEmpty() && onPick) onPick(pick);
    }

private:
    static std::int64_t stepOf(const std::deque<SignalHistory::Sample> &s) {
        return s.size() > 1 ? std::max<std::int64_t>(1000, (s.back().timeMs - s.front().timeMs) /
                                                                   std::int64_t(s.size() - 1))
                            : 1000;
    }
    double xOf(std::int64_t t, const QRectF &r) const {
        return r.left() + double(t - t0_) / double(t1_ - t0_) * r.width();
    }
    static double yOf(double cn0, const QRectF &r) {
        const double v = std::clamp(cn0, kHistoryLowCn0, kHistoryHighCn0);
        return r.bottom() - (v - kHistoryLowCn0) / (kHistoryHighCn0 - kHistoryLowCn0) * r.height();
    }
    SignalHistoryModel *model_;
    std::int64_t t0_ = 0, t1_ = 1;
};

SignalHistoryView::SignalHistoryView(SignalHistoryModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("signalHistoryView");
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    auto *bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Highlight"), this));
    chosen_ = new QLineEdit(this);
    chosen_->setObjectName("highlightSatellites");
    chosen_->setPlaceholderText(tr("satellites, e.g. G05 R12 (or click a line)"));
    chosen_->setClearButtonEnabled(true);
    bar->addWidget(chosen_, 1);
    span_ = new QComboBox(this);
    span_->setObjectName("historySpan");
    for (int minutes : {2, 10, 30, 60})
        span_->addItem(tr("last %n minute(s)", nullptr, minutes), minutes);
    span_->setCurrentIndex(span_->findData(model_->spanMinutes()));
    bar->addWidget(span_);
    layout->addLayout(bar);
    canvas_ = new Canvas(model_, this);
    layout->addWidget(canvas_, 1);
    connect(model_, &SignalHistoryModel::changed, canvas_, qOverload<>(&QWidget::update));
    connect(chosen_, &QLineEdit::textChanged, this, [this](const QString &text) {
        canvas_->chosen.clear();
        for (const QString &s : text.split(' ', Qt::SkipEmptyParts))
            canvas_->chosen.insert(s.toUpper());
        canvas_->update();
    });
    connect(span_, &QComboBox::activated, this,
            [this] { model_->setSpanMinutes(span_->currentData().toInt()); });
    canvas_->onPick = [this](const QString &label) {
        QStringList now = highlighted();
        if (now.contains(label))
            now.removeAll(label);
        else
            now << label;
        setHighlighted(now);
    };
}

void SignalHistoryView::setHighlighted(const QStringList &labels) {
    chosen_->setText(labels.join(' '));
}

QStringList SignalHistoryView::highlighted() const {
    return chosen_->text().split(' ', Qt::SkipEmptyParts);
}

void SignalHistoryView::setLive(bool live) {
    span_->setVisible(live);
    canvas_->live = live;
    canvas_->update();
}

} // namespace gnss::ui
