#include "views/cn0_map_view.h"

#include "models/signal_history_model.h"

#include <QComboBox>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace gnss::ui {

namespace {
constexpr double kMapLowCn0 = 20, kMapHighCn0 = 50;

// Weak red, through yellow, to strong green.
QColor cn0Colour(double cn0) {
    const double t = std::clamp((cn0 - kMapLowCn0) / (kMapHighCn0 - kMapLowCn0), 0.0, 1.0);
    return QColor::fromHsvF(float(t * 0.33), 0.85f, 0.9f);
}

QColor countColour(double share) {
    return QColor::fromHsvF(0.6f, float(0.15 + 0.85 * std::clamp(share, 0.0, 1.0)), 0.9f);
}
} // namespace

Cn0MapView::Cn0MapView(SignalHistoryModel *model, QWidget *parent)
    : QWidget(parent), model_(model) {
    setObjectName("cn0MapView");
    mode_ = new QComboBox(this);
    mode_->setObjectName("cn0MapMode");
    mode_->addItem(tr("Mean C/N0"));
    mode_->addItem(tr("Count"));
    mode_->move(4, 4);
    connect(mode_, &QComboBox::activated, this,
            [this](int i) { setShow(i == 0 ? Show::MeanCn0 : Show::Count); });
    connect(model_, &SignalHistoryModel::changed, this, qOverload<>(&QWidget::update));
}

void Cn0MapView::setShow(Show s) {
    show_ = s;
    mode_->setCurrentIndex(s == Show::MeanCn0 ? 0 : 1);
    update();
}

void Cn0MapView::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double top = mode_->geometry().bottom() + 4, legend = 36;
    const double side = std::min(width() - 8.0, height() - top - legend - 20);
    if (side < 40) return;
    const QPointF c(width() / 2.0, top + 10 + side / 2);
    const double R = side / 2;
    const SignalHistory &h = model_->history();
    constexpr int A = SignalHistory::kAzimuthCells, E = SignalHistory::kElevationCells;
    std::uint32_t most = 1;
    for (int e = 0; e < E; ++e)
        for (int a = 0; a < A; ++a) most = std::max(most, h.cell(a, e).count);
    // Radius by elevation: the horizon on the rim, the zenith in the middle.
    auto radius = [R](double elevation) { return R * (90 - elevation) / 90; };
    p.setPen(Qt::NoPen);
    for (int e = 0; e < E; ++e) {
        for (int a = 0; a < A; ++a) {
            const SignalHistory::Cell &cell = h.cell(a, e);
            if (!cell.count) continue;
            const double r0 = radius(e * 10.0), r1 = radius((e + 1) * 10.0);
            // Azimuth clockwise from north; Qt's angles counter-clockwise from east.
            const double start = 90 - a * 10.0, sweep = -10;
            QPainterPath path;
            path.arcMoveTo(QRectF(c.x() - r0, c.y() - r0, 2 * r0, 2 * r0), start);
            path.arcTo(QRectF(c.x() - r0, c.y() - r0, 2 * r0, 2 * r0), start, sweep);
            path.arcTo(QRectF(c.x() - r1, c.y() - r1, 2 * r1, 2 * r1), start + sweep, -sweep);
            path.closeSubpath();
            p.setBrush(show_ == Show::MeanCn0 ? cn0Colour(cell.mean())
                                              : countColour(double(cell.count) / most));
            p.drawPath(path);
        }
    }
    const QColor grid = palette().color(QPalette::Mid);
    p.setBrush(Qt::NoBrush);
    p.setPen(grid);
    for (double el : {0.0, 30.0, 60.0}) p.drawEllipse(c, radius(el), radius(el));
    p.drawLine(QPointF(c.x() - R, c.y()), QPointF(c.x() + R, c.y()));
    p.drawLine(QPointF(c.x(), c.y() - R), QPointF(c.x(), c.y() + R));
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(c.x() - 10, c.y() - R - 16, 20, 14), Qt::AlignCenter, tr("N"));
    // The legend.
    const QRectF bar(8, c.y() + R + 10, width() - 16, 10);
    for (int i = 0; i < 50; ++i) {
        const double t = i / 49.0;
        p.fillRect(QRectF(bar.left() + t * bar.width() * 49 / 50, bar.top(), bar.width() / 50 + 1,
                          bar.height()),
                   show_ == Show::MeanCn0 ? cn0Colour(kMapLowCn0 + t * (kMapHighCn0 - kMapLowCn0))
                                          : countColour(t));
    }
    const QRectF labels(bar.left(), bar.bottom() + 1, bar.width(), 14);
    if (show_ == Show::MeanCn0) {
        p.drawText(labels, Qt::AlignLeft, QString::number(kMapLowCn0));
        p.drawText(labels, Qt::AlignRight, tr("%1 dB-Hz").arg(kMapHighCn0));
    } else {
        p.drawText(labels, Qt::AlignLeft, QStringLiteral("1"));
        p.drawText(labels, Qt::AlignRight, QString::number(most));
    }
    // On a line of its own: the scale's ends take the first, however narrow the dock.
    p.drawText(labels.translated(0, 14), Qt::AlignHCenter,
               tr("%n epoch(s)", nullptr, int(h.epochs())));
}

} // namespace gnss::ui
