#include "transport_icons.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace gnss::ui {

namespace {
constexpr int kSize = 32; // drawn at 32 px, scaled down by the button

// A triangle pointing right (or left) with its base at x, width w, centred vertically.
QPainterPath triangle(double x, double w, bool right) {
    QPainterPath p;
    const double top = 8, bottom = kSize - 8;
    if (right) {
        p.moveTo(x, top);
        p.lineTo(x + w, kSize / 2.0);
        p.lineTo(x, bottom);
    } else {
        p.moveTo(x + w, top);
        p.lineTo(x, kSize / 2.0);
        p.lineTo(x + w, bottom);
    }
    p.closeSubpath();
    return p;
}
} // namespace

QIcon transportIcon(TransportIcon kind, const QColor &colour) {
    QPixmap pm(kSize, kSize);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    auto bar = [&](double x, double w = 3) { p.drawRect(QRectF(x, 8, w, kSize - 16)); };
    switch (kind) {
    case TransportIcon::Start:
        bar(7);
        p.drawPath(triangle(10, 14, false));
        break;
    case TransportIcon::PreviousEvent:
        p.drawPath(triangle(4, 12, false));
        p.drawPath(triangle(15, 12, false));
        break;
    case TransportIcon::StepBack:
        p.drawPath(triangle(9, 11, false));
        bar(21);
        break;
    case TransportIcon::Play: p.drawPath(triangle(10, 14, true)); break;
    case TransportIcon::Pause:
        bar(10, 4);
        bar(18, 4);
        break;
    case TransportIcon::StepForward:
        bar(8);
        p.drawPath(triangle(12, 11, true));
        break;
    case TransportIcon::NextEvent:
        p.drawPath(triangle(5, 12, true));
        p.drawPath(triangle(16, 12, true));
        break;
    case TransportIcon::End:
        p.drawPath(triangle(8, 14, true));
        bar(22);
        break;
    }
    return QIcon(pm);
}

} // namespace gnss::ui
