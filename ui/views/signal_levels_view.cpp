#include "views/signal_levels_view.h"
#include "models/refresh_intervals.h"

#include "models/satellite_model.h"
#include "style/gnss_style.h"

#include <QPainter>

namespace gnss::ui {
namespace {
constexpr double kMaxSnr = 60.0;
// Of a slot: the bar's inset on each side and its width; a gap between groups.
constexpr double kBarInset = 0.12, kBarShare = 0.76, kGroupGap = 0.8;
} // namespace

// The longest of "GLONASS L1OF", "R L1OF" (the letter of the ids under the bars), "L1OF" and
// "R" that fits `width`, else the first elided.
QString SignalLevelsView::groupCaption(const QFontMetricsF &fm, Constellation system, int signalId,
                                       double width) {
    const auto sig = signalName(system, signalId);
    const QString signal = QString::fromLatin1(sig.data(), int(sig.size()));
    const QString full = style::constellationName(system);
    const QString letter(QChar::fromLatin1(rinexLetter(system)));
    const QStringList candidates =
            signal.isEmpty()
                    ? QStringList{full, letter}
                    : QStringList{full + ' ' + signal, letter + ' ' + signal, signal, letter};
    for (const QString &c : candidates)
        if (fm.horizontalAdvance(c) <= width) return c;
    return fm.elidedText(candidates.front(), Qt::ElideRight, width);
}

SignalLevelsView::SignalLevelsView(SatelliteModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("signalLevels");
    auto markDirty = [this] { dirty_ = true; };
    connect(model_, &QAbstractItemModel::dataChanged, this, markDirty);
    connect(model_, &QAbstractItemModel::modelReset, this, markDirty);
    startRefreshTimer(repaintTimer_, kLiveRefreshMs, this, [this] {
        if (dirty_ && isVisible()) update();
    });
}

SignalLevelsView::Layout SignalLevelsView::layout() const {
    Layout out;
    const QFontMetricsF fm(font());
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
    const double left = fm.horizontalAdvance(QStringLiteral("60")) + 8;
    const double plotWidth = width() - left - 4;
    // Gaps between groups (constellation or signal changes).
    int groups = 0;
    for (int i = 1; i < order.size(); ++i) {
        const auto &a = rows[size_t(order[i - 1])], &b = rows[size_t(order[i])];
        if (a.sat.system != b.sat.system || a.signalId != b.signalId) ++groups;
    }
    const double slot =
            order.isEmpty() ? plotWidth : plotWidth / (order.size() + groups * kGroupGap);
    out.slot = slot;
    // Ids: the normal font shrunk to no less than 7 pt; level when the widest fits its slot, on
    // end when a line of text fits it, else on end and thinned out.
    out.idFont = font();
    QString widest = QStringLiteral("G00");
    for (int i : order) {
        const QString id = QString::fromStdString(satelliteLabel(rows[size_t(i)].sat));
        if (id.size() > widest.size()) widest = id;
    }
    QFontMetricsF ifm(out.idFont);
    while (ifm.horizontalAdvance(widest) > slot - 2 && out.idFont.pointSizeF() > 7) {
        out.idFont.setPointSizeF(std::max(7.0, out.idFont.pointSizeF() - 0.5));
        ifm = QFontMetricsF(out.idFont);
    }
    const double textWidth = ifm.horizontalAdvance(widest);
    out.rotated = textWidth > slot - 2;
    if (out.rotated) out.every = std::max(1, int(std::ceil((ifm.height() + 1) / slot)));
    const double idBand = (out.rotated ? textWidth : ifm.height()) + 4;
    out.area = QRectF(left, fm.height() * 0.6, plotWidth,
                      std::max(10.0, height() - fm.height() * 0.6 - idBand - fm.height() * 1.4));
    if (order.isEmpty()) return out;

    double x = out.area.left();
    double lastIdRight = -1e9; // ids are written left to right, each clear of the one before
    for (int i = 0; i < order.size(); ++i) {
        const auto &r = rows[size_t(order[i])];
        if (i > 0) {
            const auto &prev = rows[size_t(order[i - 1])];
            if (prev.sat.system != r.sat.system || prev.signalId != r.signalId)
                x += slot * kGroupGap;
        }
        const double snr = std::clamp(double(r.snr.value_or(0)), 0.0, kMaxSnr);
        const double h = out.area.height() * snr / kMaxSnr;
        Bar b{order[i], QRectF(x + slot * kBarInset, out.area.bottom() - h, slot * kBarShare, h),
              SatelliteModel::label(r), QString(), QRectF()};
        const QString id = QString::fromStdString(satelliteLabel(r.sat));
        const double cx = x + slot / 2, top = out.area.bottom() + 2;
        const double tw = ifm.horizontalAdvance(id), th = ifm.height();
        const QRectF idRect =
                out.rotated ? QRectF(cx - th / 2, top, th, tw) : QRectF(cx - tw / 2, top, tw, th);
        if (idRect.left() > lastIdRight + 1) { // else thinned out: no room beside the last
            b.id = id;
            b.idRect = idRect;
            lastIdRight = idRect.right();
        }
        out.bars.push_back(b);
        x += slot;
    }
    return out;
}

void SignalLevelsView::paintEvent(QPaintEvent *) {
    dirty_ = false;
    QPainter p(this);
    const QPalette pal = palette();
    const Layout lay = layout();
    const QRectF &area = lay.area;
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
    const auto &bars = lay.bars;
    if (bars.isEmpty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(area, Qt::AlignCenter, tr("No satellites in view"));
        return;
    }
    const auto &rows = model_->rows();
    p.setFont(lay.idFont);
    const QFontMetricsF sfm(lay.idFont);
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
        // The SNR above the bar when it fits level across it.
        const QString snr = QString::number(r.snr.value_or(0));
        if (r.snr && b.rect.height() > sfm.height() &&
            sfm.horizontalAdvance(snr) <= b.rect.width() + 4)
            p.drawText(QRectF(b.rect.left() - 4, b.rect.top() - sfm.height(), b.rect.width() + 8,
                              sfm.height()),
                       Qt::AlignCenter, snr);
        if (b.id.isEmpty()) continue;
        if (lay.rotated) {
            // Read from top to bottom, centred on the bar.
            p.save();
            p.translate(b.idRect.left() + sfm.descent(), b.idRect.top());
            p.rotate(90);
            p.drawText(QPointF(0, 0), b.id);
            p.restore();
        } else {
            p.drawText(b.idRect, Qt::AlignCenter, b.id);
        }
    }
    // Signal names under each group, fitted to its span.
    p.setFont(font());
    int start = 0;
    for (int i = 1; i <= bars.size(); ++i) {
        const auto &first = rows[size_t(bars[start].row)];
        const bool end = i == bars.size() ||
                         rows[size_t(bars[i].row)].sat.system != first.sat.system ||
                         rows[size_t(bars[i].row)].signalId != first.signalId;
        if (!end) continue;
        // The group's bars and half the gap on each side.
        const double margin = lay.slot * (kBarInset + kGroupGap / 2) - 2;
        const QRectF span(bars[start].rect.left() - margin, height() - fm.height() * 1.2,
                          bars[i - 1].rect.right() - bars[start].rect.left() + 2 * margin,
                          fm.height());
        p.setPen(style::constellationColor(first.sat.system));
        p.drawText(span, Qt::AlignCenter,
                   groupCaption(fm, first.sat.system, first.signalId, span.width()));
        start = i;
    }
}

} // namespace gnss::ui
