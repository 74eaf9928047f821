#include "app_icon.h"

#include "gnss_style.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace gnss::style {

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
    QPainterPath diamond;
    diamond.moveTo(76, 80);
    diamond.lineTo(86, 90);
    diamond.lineTo(76, 100);
    diamond.lineTo(66, 90);
    diamond.closeSubpath();
    p.fillPath(diamond, constellationColor(Constellation::Galileo));
    QPainterPath triangle;
    triangle.moveTo(44, 96);
    triangle.lineTo(53, 80);
    triangle.lineTo(62, 96);
    triangle.closeSubpath();
    p.fillPath(triangle, constellationColor(Constellation::BeiDou));
    return pm;
}

QIcon appIcon() {
    QIcon icon;
    // The hicolor theme's sizes: what panels, title bars and task switchers ask for.
    for (int size : {16, 22, 24, 32, 48, 64, 128, 256}) icon.addPixmap(appIconPixmap(size));
    return icon;
}

} // namespace gnss::style
