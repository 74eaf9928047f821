#include "logview/transport_icons.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

#include <optional>

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

// The forward icons are the backward ones mirrored: the one each mirrors, if any.
std::optional<TransportIcon> mirrorOf(TransportIcon kind) {
    switch (kind) {
    case TransportIcon::StepForward: return TransportIcon::StepBack;
    case TransportIcon::NextEvent: return TransportIcon::PreviousEvent;
    case TransportIcon::End: return TransportIcon::Start;
    default: return std::nullopt;
    }
}
} // namespace

QIcon transportIcon(TransportIcon kind, const QColor &colour) {
    QPixmap pm(kSize, kSize);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    if (const auto backward = mirrorOf(kind)) {
        p.translate(kSize, 0);
        p.scale(-1, 1);
        kind = *backward;
    }
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
    case TransportIcon::NextEvent:
    case TransportIcon::End: break; // drawn as their mirror images, above
    }
    return QIcon(pm);
}

} // namespace gnss::ui
