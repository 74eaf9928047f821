#include "signal_levels_view.h"

#include "models/satellite_model.h"
#include "style/gnss_style.h"

#include <QPainter>

namespace gnss::ui {
namespace {
constexpr double kMaxSnr = 60.0;
}

SignalLevelsView::SignalLevelsView(SatelliteModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("signalLevels");
    auto markDirty = [this] { dirty_ = true; };
    connect(model_, &QAbstractItemModel::dataChanged, this, markDirty);
    connect(model_, &QAbstractItemModel::modelReset, this, markDirty);
    repaintTimer_.setInterval(100);
    connect(&repaintTimer_, &QTimer::timeout, this, [this] {
        if (dirty_ && isVisible()) update();
    });
    repaintTimer_.start();
}

QRectF SignalLevelsView::plotArea() const {
    const QFontMetricsF fm(font());
    const double left = fm.horizontalAdvance(QStringLiteral("60")) + 8;
    return QRectF(left, fm.height() * 0.6, width() - left - 4, height() - fm.height() * 3.4);
}

QVector<SignalLevelsView::Bar> SignalLevelsView::layoutBars() const {
    QVector<Bar> bars;
    const auto &rows = model_->rows(); // sorted by constellation, PRN, signal
    // Order within a constellation: by signal, then PRN (so each signal's bars stand together).
    QVector<int> order;
    for (int i = 0; i < int(rows.size()); ++i)
        if (rows[size_t(i)].inView && rows[size_t(i)].snr)
            order.push_back(i); // a bar needs a signal
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const auto &x = rows[size_t(a)], &y = rows[size_t(b)];
        if (x.sat.system != y.sat.system) return x.sat.system < y.sat.system;
        if (x.signalId != y.signalId) return x.signalId < y.signalId;
        return x.sat.prn < y.sat.prn;
    });
    if (order.isEmpty()) return bars;
    // Gaps between groups (constellation or signal changes).
    int groups = 0;
    for (int i = 1; i < order.size(); ++i) {
        const auto &a = rows[size_t(order[i - 1])], &b = rows[size_t(order[i])];
        if (a.sat.system != b.sat.system || a.signalId != b.signalId) ++groups;
    }
    const QRectF area = plotArea();
    const double slotCount = order.size() + groups * 0.8;
    const double w = area.width() / slotCount;
    double x = area.left();
    for (int i = 0; i < order.size(); ++i) {
        const auto &r = rows[size_t(order[i])];
        if (i > 0) {
            const auto &prev = rows[size_t(order[i - 1])];
            if (prev.sat.system != r.sat.system || prev.signalId != r.signalId) x += w * 0.8;
        }
        const double snr = std::clamp(double(r.snr.value_or(0)), 0.0, kMaxSnr);
        const double h = area.height() * snr / kMaxSnr;
        bars.push_back({order[i], QRectF(x + w * 0.12, area.bottom() - h, w * 0.76, h),
                        SatelliteModel::label(r)});
        x += w;
    }
    return bars;
}

void SignalLevelsView::paintEvent(QPaintEvent *) {
    dirty_ = false;
    QPainter p(this);
    const QPalette pal = palette();
    const QRectF area = plotArea();
    const QFontMetricsF fm(font());
    p.fillRect(area, pal.color(QPalette::Base));
    // SNR grid every 10 dB-Hz.
    for (int s = 0; s <= kMaxSnr; s += 10) {
        const double y = area.bottom() - area.height() * s / kMaxSnr;
        p.setPen(QPen(pal.color(QPalette::Midlight), 1));
        p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
        p.setPen(pal.color(QPalette::WindowText));
        p.drawText(QRectF(0, y - fm.height() / 2, area.left() - 4, fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, QString::number(s));
    }
    const auto bars = layoutBars();
    if (bars.isEmpty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(area, Qt::AlignCenter, tr("No satellites in view"));
        return;
    }
    const auto &rows = model_->rows();
    QFont small = font();
    const double barWidth = bars.front().rect.width();
    small.setPointSizeF(std::max(6.0, std::min(font().pointSizeF(), barWidth * 0.45)));
    p.setFont(small);
    const QFontMetricsF sfm(small);
    const bool vertical = sfm.horizontalAdvance(QStringLiteral("G00")) > barWidth * 1.3;
    for (const Bar &b : bars) {
        const auto &r = rows[size_t(b.row)];
        const QColor col = style::constellationColor(r.sat.system);
        if (r.used) {
            p.setPen(QPen(col.darker(130), 1));
            p.setBrush(col);
        } else {
            p.setPen(QPen(col, 1.5));
            p.setBrush(QColor(col.red(), col.green(), col.blue(), 40));
        }
        if (b.rect.height() > 0) p.drawRect(b.rect);
        p.setPen(pal.color(QPalette::WindowText));
        if (r.snr && b.rect.height() > sfm.height() && !vertical)
            p.drawText(QRectF(b.rect.left() - 4, b.rect.top() - sfm.height(), b.rect.width() + 8,
                              sfm.height()),
                       Qt::AlignCenter, QString::number(*r.snr));
        // Id below the bar.
        const QString id = QString::fromStdString(satelliteLabel(r.sat));
        if (vertical) {
            p.save();
            p.translate(b.rect.center().x() + sfm.ascent() / 2, area.bottom() + 3);
            p.rotate(90);
            p.drawText(QPointF(0, 0), id);
            p.restore();
        } else {
            p.drawText(
                    QRectF(b.rect.left() - 6, area.bottom() + 2, b.rect.width() + 12, sfm.height()),
                    Qt::AlignCenter, id);
        }
    }
    // Signal names under each group.
    p.setFont(font());
    int start = 0;
    for (int i = 1; i <= bars.size(); ++i) {
        const auto &first = rows[size_t(bars[start].row)];
        const bool end = i == bars.size() ||
                         rows[size_t(bars[i].row)].sat.system != first.sat.system ||
                         rows[size_t(bars[i].row)].signalId != first.signalId;
        if (!end) continue;
        const auto sig = signalName(first.sat.system, first.signalId);
        QString name = QString::fromLatin1(toString(first.sat.system).data());
        if (!sig.empty()) name += ' ' + QString::fromLatin1(sig.data(), int(sig.size()));
        const QRectF span(bars[start].rect.left(), height() - fm.height() * 1.2,
                          bars[i - 1].rect.right() - bars[start].rect.left(), fm.height());
        p.setPen(style::constellationColor(first.sat.system));
        p.drawText(span, Qt::AlignCenter, fm.elidedText(name, Qt::ElideRight, span.width()));
        start = i;
    }
}

} // namespace gnss::ui
