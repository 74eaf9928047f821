#include "style/gnss_style.h"

#include <QCoreApplication>

namespace gnss::style {

QColor constellationColor(Constellation c) {
    switch (c) {
    case Constellation::Gps: return QColor(0x00, 0x72, 0xB2);
    case Constellation::Glonass: return QColor(0xD5, 0x5E, 0x00);
    case Constellation::Galileo: return QColor(0x00, 0x9E, 0x73);
    case Constellation::BeiDou: return QColor(0xCC, 0x79, 0xA7);
    case Constellation::Qzss: return QColor(0xE6, 0x9F, 0x00);
    case Constellation::Sbas: return QColor(0x99, 0x99, 0x99);
    case Constellation::NavIC: return QColor(0x56, 0xB4, 0xE9);
    case Constellation::Unknown: break;
    }
    return QColor(0x60, 0x60, 0x60);
}

Marker constellationMarker(Constellation c) {
    switch (c) {
    case Constellation::Gps: return Marker::Circle;
    case Constellation::Glonass: return Marker::Square;
    case Constellation::Galileo: return Marker::Diamond;
    case Constellation::BeiDou: return Marker::TriangleUp;
    case Constellation::Qzss: return Marker::Pentagon;
    case Constellation::Sbas: return Marker::TriangleDown;
    case Constellation::NavIC: return Marker::Star;
    case Constellation::Unknown: break;
    }
    return Marker::Circle;
}

QString constellationName(Constellation c) {
    if (c == Constellation::Unknown)
        return QCoreApplication::translate("Constellation", "unknown system");
    return QString::fromLatin1(toString(c).data(), int(toString(c).size()));
}

QString fixTypeLabel(FixType f) {
    switch (f) {
    case FixType::None: return QCoreApplication::translate("FixType", "No fix");
    case FixType::Estimated: return QCoreApplication::translate("FixType", "Estimated");
    case FixType::Fix2D: return QCoreApplication::translate("FixType", "2D");
    case FixType::Fix3D: return QCoreApplication::translate("FixType", "3D");
    case FixType::Dgnss: return QCoreApplication::translate("FixType", "DGNSS");
    case FixType::RtkFloat: return QCoreApplication::translate("FixType", "RTK float");
    case FixType::RtkFixed: return QCoreApplication::translate("FixType", "RTK fixed");
    case FixType::Manual: return QCoreApplication::translate("FixType", "Fixed position");
    case FixType::Simulator: return QCoreApplication::translate("FixType", "Simulator");
    }
    return {};
}

QColor fixTypeColor(FixType f) {
    switch (f) {
    case FixType::None: return QColor(0x9E, 0x9E, 0x9E);      // grey
    case FixType::Estimated: return QColor(0x7B, 0x1F, 0xA2); // purple
    case FixType::Fix2D: return QColor(0xFF, 0xB3, 0x00);     // amber
    case FixType::Fix3D: return QColor(0x1E, 0x88, 0xE5);     // blue
    case FixType::Dgnss: return QColor(0x00, 0x89, 0x7B);     // teal
    case FixType::RtkFloat: return QColor(0xFB, 0x8C, 0x00);  // orange
    case FixType::RtkFixed: return QColor(0x43, 0xA0, 0x47);  // green
    case FixType::Manual: return QColor(0x42, 0x42, 0x42);    // dark grey
    case FixType::Simulator: return QColor(0x42, 0x42, 0x42);
    }
    return QColor(0x9E, 0x9E, 0x9E);
}

} // namespace gnss::style

namespace gnss::style {

QColor errorColor() {
    return QColor(0xc6, 0x28, 0x28);
}

QColor okColor() {
    return QColor(0x2e, 0x7d, 0x32);
}

QColor cautionColor() {
    return lineColor(LineTone::Vermillion);
}

QColor mutedColor() {
    return QColor(0xa0, 0xa0, 0xa4); // Qt::gray
}

QColor sentColor() {
    return lineColor(LineTone::Blue);
}

QColor lineColor(LineTone t) {
    switch (t) {
    case LineTone::Blue: return constellationColor(Constellation::Gps);
    case LineTone::Vermillion: return constellationColor(Constellation::Glonass);
    case LineTone::BluishGreen: return constellationColor(Constellation::Galileo);
    case LineTone::ReddishPurple: return constellationColor(Constellation::BeiDou);
    }
    return constellationColor(Constellation::Gps);
}

QString textColorCss(const QColor &c) {
    return QStringLiteral("color: %1;").arg(c.name());
}

QColor badgeTextColor() {
    return QColor(Qt::white);
}

QString badgeCss(const QColor &background, int radius, const char *padding) {
    return QStringLiteral("background: %1; %2 border-radius: %3px; padding: %4;")
            .arg(background.name(), textColorCss(badgeTextColor()))
            .arg(radius)
            .arg(QLatin1String(padding));
}

} // namespace gnss::style
