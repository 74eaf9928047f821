#include "style/app_icon.h"

#include "style/gnss_style.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QPolygonF>

namespace gnss::style {

namespace {
// The closed outline through `corners`, in order.
QPainterPath closedPath(std::initializer_list<QPointF> corners) {
    QPainterPath path;
    path.addPolygon(QPolygonF(corners));
    path.closeSubpath();
    return path;
}
} // namespace

QPixmap appIconPixmap(int size) {
    QPixmap pm(size, size);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 128.0, size / 128.0);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x1f, 0x29, 0x33));
    p.drawRoundedRect(QRectF(4, 4, 120, 120), 22, 22);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(0x9a, 0xa5, 0xb1), 3));
    p.drawEllipse(QPointF(64, 64), 48, 48);
    p.setPen(QPen(QColor(0x61, 0x6e, 0x7c), 2));
    p.drawEllipse(QPointF(64, 64), 32, 32);
    p.drawEllipse(QPointF(64, 64), 16, 16);
    p.setPen(QPen(QColor(0x52, 0x60, 0x6d), 2));
    p.drawLine(QPointF(64, 16), QPointF(64, 112));
    p.drawLine(QPointF(16, 64), QPointF(112, 64));
    p.setPen(Qt::NoPen);
    p.setBrush(constellationColor(Constellation::Gps));
    p.drawEllipse(QPointF(86, 40), 9, 9);
    p.setBrush(constellationColor(Constellation::Glonass));
    p.drawRect(QRectF(30, 42, 16, 16));
    p.fillPath(closedPath({{76, 80}, {86, 90}, {76, 100}, {66, 90}}),
               constellationColor(Constellation::Galileo)); // diamond
    p.fillPath(closedPath({{44, 96}, {53, 80}, {62, 96}}),
               constellationColor(Constellation::BeiDou)); // triangle
    return pm;
}

QIcon appIcon() {
    QIcon icon;
    // The hicolor theme's sizes: what panels, title bars and task switchers ask for.
    for (int size : {16, 22, 24, 32, 48, 64, 128, 256}) icon.addPixmap(appIconPixmap(size));
    return icon;
}

} // namespace gnss::style
