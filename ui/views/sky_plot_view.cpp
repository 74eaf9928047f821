#include "views/sky_plot_view.h"
#include "models/refresh_intervals.h"

#include "models/satellite_model.h"
#include "style/gnss_style.h"

#include "core/wgs84.h"

#include <QContextMenuEvent>
#include <QHelpEvent>
#include <QMenu>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <cmath>
#include <numeric>

namespace gnss::ui {

void drawConstellationMarker(QPainter &p, Constellation c, QPointF o, double s) {
    const double h = s / 2;
    QPainterPath path;
    auto polygon = [&](int n, double rot, double r) {
        for (int i = 0; i < n; ++i) {
            const double a = rot + 2 * wgs84::kPi * i / n;
            const QPointF q(o.x() + r * std::sin(a), o.y() - r * std::cos(a));
            i == 0 ? path.moveTo(q) : path.lineTo(q);
        }
        path.closeSubpath();
    };
    switch (style::constellationMarker(c)) {
    case style::Marker::Circle: path.addEllipse(o, h, h); break;
    case style::Marker::Square:
        path.addRect(QRectF(o.x() - h * 0.9, o.y() - h * 0.9, s * 0.9, s * 0.9));
        break;
    case style::Marker::Diamond: polygon(4, 0, h * 1.2); break;
    case style::Marker::TriangleUp: polygon(3, 0, h * 1.2); break;
    case style::Marker::TriangleDown: polygon(3, wgs84::kPi, h * 1.2); break;
    case style::Marker::Pentagon: polygon(5, 0, h * 1.1); break;
    case style::Marker::Star: {
        for (int i = 0; i < 10; ++i) {
            const double a = 2 * wgs84::kPi * i / 10;
            const double r = i % 2 ? h * 0.5 : h * 1.2;
            const QPointF q(o.x() + r * std::sin(a), o.y() - r * std::cos(a));
            i == 0 ? path.moveTo(q) : path.lineTo(q);
        }
        path.closeSubpath();
        break;
    }
    }
    p.drawPath(path);
}

SkyPlotView::SkyPlotView(SatelliteModel *model, QWidget *parent) : QWidget(parent), model_(model) {
    setObjectName("skyPlot");
    setMouseTracking(true);
    auto markDirty = [this] { dirty_ = true; };
    connect(model_, &QAbstractItemModel::dataChanged, this, markDirty);
    connect(model_, &QAbstractItemModel::modelReset, this, markDirty);
    startRefreshTimer(repaintTimer_, kLiveRefreshMs, this, [this] {
        if (dirty_ && isVisible()) update();
    });
}

void SkyPlotView::setShowTracks(bool on) {
    showTracks_ = on;
    dirty_ = true;
}
void SkyPlotView::setShowLabels(bool on) {
    showLabels_ = on;
    dirty_ = true;
}
void SkyPlotView::setElevationMask(double d) {
    mask_ = d;
    dirty_ = true;
}
void SkyPlotView::setConstellationVisible(Constellation c, bool visible) {
    if (visible)
        hidden_.remove(int(c));
    else
        hidden_.insert(int(c));
    dirty_ = true;
}

double SkyPlotView::radius() const {
    const QFontMetrics fm(font());
    return std::max(10.0, std::min(width(), height()) / 2.0 - fm.height() * 1.6);
}

QPointF SkyPlotView::center() const {
    return QPointF(width() / 2.0, height() / 2.0);
}

QPointF SkyPlotView::project(double az, double el) const {
    const double rho = radius() * (90.0 - std::clamp(el, 0.0, 90.0)) / 90.0;
    const double a = wgs84::radians(az);
    const QPointF c = center();
    return {c.x() + rho * std::sin(a), c.y() - rho * std::cos(a)};
}

QVector<SkyPlotView::Marker> SkyPlotView::markers() const {
    QVector<Marker> out;
    QHash<quint64, int> bySat;
    for (const SatelliteRow &r : model_->rows()) {
        if (!r.inView || !r.elevation || !r.azimuth || *r.elevation < 0) continue;
        if (hidden_.contains(int(r.sat.system))) continue;
        const quint64 k = (quint64(quint8(r.sat.system)) << 32) | quint32(r.sat.prn);
        const QString sig = SatelliteModel::label(r);
        const QString line =
                tr("%1: SNR %2 dB-Hz%3")
                        .arg(sig, r.snr ? QString::number(*r.snr) : QStringLiteral("—"),
                             r.used ? tr(", used") : QString());
        auto it = bySat.find(k);
        if (it == bySat.end()) {
            Marker m;
            m.sat = r.sat;
            m.pos = project(*r.azimuth, *r.elevation);
            m.snr = r.snr.value_or(-1);
            m.used = r.used;
            m.label = QString::fromStdString(satelliteLabel(r.sat));
            m.tooltip = tr("%1 (%2)\nelevation %3°, azimuth %4°")
                                .arg(m.label, QString::fromLatin1(toString(r.sat.system).data()))
                                .arg(*r.elevation)
                                .arg(*r.azimuth) +
                        '\n' + line;
            bySat.insert(k, int(out.size()));
            out.push_back(m);
        } else {
            Marker &m = out[*it];
            m.snr = std::max(m.snr, r.snr.value_or(-1));
            m.used |= r.used;
            m.tooltip += '\n' + line;
        }
    }
    if (showLabels_) placeLabels(out);
    return out;
}

double SkyPlotView::markerSize() const {
    return std::max(9.0, QFontMetricsF(font()).height() * 0.9);
}

QFont SkyPlotView::labelFont() const {
    QFont small = font();
    small.setPointSizeF(font().pointSizeF() * 0.8);
    return small;
}

void SkyPlotView::placeLabels(QVector<Marker> &ms) const {
    const QFontMetricsF fm(labelFont());
    const double size = markerSize();
    const QRectF bounds = rect();
    // Markers are obstacles too: a label never hides a satellite.
    QVector<QRectF> taken;
    taken.reserve(ms.size() * 2);
    for (const Marker &m : ms)
        taken.push_back(
                QRectF(m.pos - QPointF(size * 0.65, size * 0.65), QSizeF(size * 1.3, size * 1.3)));
    // And the compass letters and ring degrees: "G26" written over the W read "GW6".
    for (const GridText &t : gridTexts()) taken.push_back(t.rect);
    // Used satellites first, then the strongest: when there is no room, the weak lose their label.
    QVector<int> order(ms.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        if (ms[a].used != ms[b].used) return ms[a].used;
        return ms[a].snr > ms[b].snr;
    });
    const double gap = size * 0.7;
    // The first free place for a label of size `ts` near marker i: the eight places around it,
    // then the same further out (drawn with a leader line back to the marker).
    auto place = [&](int i, QSizeF ts, bool &leader) -> QRectF {
        const QPointF offsets[] = {
                {gap, -ts.height() / 2},
                {-gap - ts.width(), -ts.height() / 2},
                {-ts.width() / 2, -gap - ts.height()},
                {-ts.width() / 2, gap},
                {gap * 0.7, -gap * 0.7 - ts.height()},
                {gap * 0.7, gap * 0.7},
                {-gap * 0.7 - ts.width(), -gap * 0.7 - ts.height()},
                {-gap * 0.7 - ts.width(), gap * 0.7},
        };
        for (double reach : {1.0, 2.2}) {
            for (const QPointF &o : offsets) {
                const QPointF shift = reach == 1.0 ? QPointF()
                                                   : o / std::max(1.0, std::hypot(o.x(), o.y())) *
                                                             gap * (reach - 1) * 1.5;
                const QRectF r(ms[i].pos + o + shift, ts);
                if (!bounds.contains(r)) continue;
                bool free = true;
                for (int k = 0; k < taken.size() && free; ++k)
                    if (k != i && taken[k].intersects(r)) free = false;
                if (free) {
                    leader = reach > 1.0;
                    return r;
                }
            }
        }
        return {};
    };
    for (int i : order) {
        Marker &m = ms[i];
        // "G05 42" where it fits, else just "G05" (the SNR is in the tooltip), else nothing.
        QStringList texts;
        if (m.snr >= 0) texts << QStringLiteral("%1 %2").arg(m.label).arg(m.snr);
        texts << m.label;
        m.labelRect = {};
        m.text.clear();
        for (const QString &t : texts) {
            m.labelRect = place(i, QSizeF(fm.horizontalAdvance(t) + 2, fm.height()), m.leader);
            if (m.labelRect.isNull()) continue;
            m.text = t;
            taken.push_back(m.labelRect);
            break;
        }
    }
}

QVector<SkyPlotView::GridText> SkyPlotView::gridTexts() const {
    const QFontMetricsF fm(font());
    const QPointF c = center();
    const double r = radius();
    const double off = fm.height() * 0.8;
    QVector<GridText> out;
    auto centred = [&](const QString &s, QPointF at) {
        const double w = fm.horizontalAdvance(s) + 2;
        out.push_back({s, QRectF(at.x() - w / 2, at.y() - fm.height() / 2, w, fm.height())});
    };
    centred(tr("N"), QPointF(c.x(), c.y() - r - off));
    centred(tr("S"), QPointF(c.x(), c.y() + r + off));
    centred(tr("E"), QPointF(c.x() + r + off, c.y()));
    centred(tr("W"), QPointF(c.x() - r - off, c.y()));
    for (int el : {0, 30, 60}) {
        const QString s = QStringLiteral("%1°").arg(el);
        out.push_back({s,
                       QRectF(c.x() + 3, c.y() - r * (90 - el) / 90.0, fm.horizontalAdvance(s) + 2,
                              fm.height()),
                       true});
    }
    return out;
}

void SkyPlotView::paintEvent(QPaintEvent *) {
    dirty_ = false;
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const QColor grid = pal.color(QPalette::Mid);
    const QColor text = pal.color(QPalette::WindowText);
    const QPointF c = center();
    const double r = radius();

    // Horizon, elevation rings every 30°, cardinal lines.
    p.setPen(QPen(grid, 1));
    p.setBrush(pal.color(QPalette::Base));
    p.drawEllipse(c, r, r);
    p.setBrush(Qt::NoBrush);
    for (int el : {30, 60}) {
        const double rr = r * (90 - el) / 90.0;
        p.drawEllipse(c, rr, rr);
    }
    p.drawLine(QPointF(c.x(), c.y() - r), QPointF(c.x(), c.y() + r));
    p.drawLine(QPointF(c.x() - r, c.y()), QPointF(c.x() + r, c.y()));
    for (const GridText &t : gridTexts()) {
        p.setPen(t.ring ? grid : text);
        p.drawText(t.rect, t.ring ? Qt::AlignLeft | Qt::AlignTop : Qt::AlignCenter, t.text);
    }

    // Elevation mask.
    if (mask_ > 0) {
        QColor mask = style::errorColor();
        mask.setAlpha(160);
        QPen pen(mask, 1.5, Qt::DashLine);
        p.setPen(pen);
        const double rr = r * (90 - mask_) / 90.0;
        p.drawEllipse(c, rr, rr);
    }

    // Tracks.
    if (showTracks_) {
        QSet<quint64> drawn;
        for (const SatelliteRow &row : model_->rows()) {
            if (hidden_.contains(int(row.sat.system))) continue;
            const quint64 k = (quint64(quint8(row.sat.system)) << 32) | quint32(row.sat.prn);
            if (drawn.contains(k)) continue;
            drawn.insert(k);
            const auto *t = model_->track(row);
            if (!t || t->size() < 2) continue;
            QPainterPath path;
            bool first = true;
            for (const TrackPoint &tp : *t) {
                const QPointF q = project(tp.azimuth, tp.elevation);
                first ? path.moveTo(q) : path.lineTo(q);
                first = false;
            }
            QColor col = style::constellationColor(row.sat.system);
            col.setAlpha(110);
            p.setPen(QPen(col, 1.5));
            p.setBrush(Qt::NoBrush);
            p.drawPath(path);
        }
    }

    // Satellites.
    const double size = markerSize();
    const QFont small = labelFont();
    const auto ms = markers();
    for (const Marker &m : ms) {
        QColor col = style::constellationColor(m.sat.system);
        if (m.snr < 0) { // in view, no signal: dashed and dimmed
            col.setAlpha(120);
            p.setPen(QPen(col, 1.2, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
        } else if (m.used) {
            p.setPen(QPen(col.darker(130), 1.2));
            p.setBrush(col);
        } else {
            p.setPen(QPen(col, 2));
            p.setBrush(Qt::NoBrush);
        }
        drawConstellationMarker(p, m.sat.system, m.pos, size);
    }
    // Labels after every marker, in the places found for them.
    p.setFont(small);
    for (const Marker &m : ms) {
        if (m.text.isEmpty()) continue;
        if (m.leader) {
            p.setPen(QPen(grid, 1));
            const QPointF to = m.labelRect.center();
            const QPointF dir = (to - m.pos) /
                                std::max(1.0, std::hypot(to.x() - m.pos.x(), to.y() - m.pos.y()));
            p.drawLine(m.pos + dir * size * 0.7,
                       QPointF(std::clamp(m.pos.x(), m.labelRect.left(), m.labelRect.right()),
                               std::clamp(m.pos.y(), m.labelRect.top(), m.labelRect.bottom())));
        }
        p.setPen(text);
        p.drawText(m.labelRect, Qt::AlignCenter, m.text);
    }
    p.setFont(font());
}

bool SkyPlotView::event(QEvent *e) {
    if (e->type() == QEvent::ToolTip) {
        auto *he = static_cast<QHelpEvent *>(e);
        const QPointF at = he->pos();
        const Marker *best = nullptr;
        double bestD = 14 * 14;
        const auto ms = markers();
        for (const Marker &m : ms) {
            const QPointF d = m.pos - at;
            const double dd = d.x() * d.x() + d.y() * d.y();
            if (dd < bestD) {
                bestD = dd;
                best = &m;
            }
        }
        if (best)
            QToolTip::showText(he->globalPos(), best->tooltip, this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(e);
}

void SkyPlotView::contextMenuEvent(QContextMenuEvent *e) {
    QMenu menu(this);
    QAction *tracks = menu.addAction(tr("Show tracks"));
    tracks->setCheckable(true);
    tracks->setChecked(showTracks_);
    connect(tracks, &QAction::toggled, this, &SkyPlotView::setShowTracks);
    QAction *labels = menu.addAction(tr("Show labels"));
    labels->setCheckable(true);
    labels->setChecked(showLabels_);
    connect(labels, &QAction::toggled, this, &SkyPlotView::setShowLabels);
    QMenu *systems = menu.addMenu(tr("Constellations"));
    for (Constellation c :
         {Constellation::Gps, Constellation::Glonass, Constellation::Galileo, Constellation::BeiDou,
          Constellation::Qzss, Constellation::Sbas, Constellation::NavIC}) {
        QAction *a = systems->addAction(QString::fromLatin1(toString(c).data()));
        a->setCheckable(true);
        a->setChecked(constellationVisible(c));
        connect(a, &QAction::toggled, this, [this, c](bool on) { setConstellationVisible(c, on); });
    }
    menu.exec(e->globalPos());
}

} // namespace gnss::ui
