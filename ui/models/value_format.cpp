#include "models/value_format.h"

#include "core/field_types.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QTimeZone>

#include <array>
#include <cmath>

namespace gnss::ui {

namespace {

template <typename E, std::size_t N>
E fromKey(const std::array<const char *, N> &keys, const QString &key, E fallback) {
    for (std::size_t i = 0; i < N; ++i)
        if (key == QLatin1String(keys[i])) return static_cast<E>(i);
    return fallback;
}
constexpr std::array<const char *, 3> kUnitKeys = {"metric", "imperial", "nautical"};
constexpr std::array<const char *, 3> kCoordinateKeys = {"deg", "dm", "dms"};
constexpr std::array<const char *, 2> kTimeKeys = {"utc", "local"};

QString unitText(const char *text) {
    return QCoreApplication::translate("Units", text);
}

} // namespace

QString toKey(UnitSystem u) {
    return QLatin1String(kUnitKeys[std::size_t(u)]);
}
QString toKey(CoordinateFormat c) {
    return QLatin1String(kCoordinateKeys[std::size_t(c)]);
}
QString toKey(TimeZoneChoice t) {
    return QLatin1String(kTimeKeys[std::size_t(t)]);
}
UnitSystem unitSystemFromKey(const QString &key, UnitSystem fallback) {
    return fromKey(kUnitKeys, key, fallback);
}
CoordinateFormat coordinateFormatFromKey(const QString &key, CoordinateFormat fallback) {
    return fromKey(kCoordinateKeys, key, fallback);
}
TimeZoneChoice timeZoneFromKey(const QString &key, TimeZoneChoice fallback) {
    return fromKey(kTimeKeys, key, fallback);
}

namespace fmt {

QString dash() {
    return QStringLiteral("—");
}

QString number(const std::optional<double> &v, int decimals, const QString &unit) {
    if (!v || !std::isfinite(*v)) return dash();
    QString s = QString::number(*v, 'f', decimals);
    return unit.isEmpty() ? s : s + ' ' + unit;
}

QString integer(const std::optional<int> &v, const QString &unit) {
    if (!v) return dash();
    return unit.isEmpty() ? QString::number(*v) : QString::number(*v) + ' ' + unit;
}

QString count(const std::optional<std::int64_t> &v) {
    return v ? QString::number(*v) : dash();
}

QString angle(const std::optional<double> &degrees, int decimals) {
    return degrees ? number(degrees, decimals) + QChar(0x00B0) : dash();
}

namespace {

// Rounds `x` to `decimals` and carries what would show as 60 into the next unit up.
bool carries(double &x, int decimals) {
    const double limit = 60.0 - 0.5 * std::pow(10.0, -decimals);
    if (x < limit) return false;
    x = 0;
    return true;
}

QString coordinate(const std::optional<double> &deg, CoordinateFormat f, const char *pos,
                   const char *neg) {
    if (!deg || !std::isfinite(*deg)) return dash();
    const double a = std::abs(*deg);
    const QString hemi = QCoreApplication::translate("Hemisphere", *deg < 0 ? neg : pos);
    int d = int(a);
    switch (f) {
    case CoordinateFormat::Degrees: return QStringLiteral("%1° %2").arg(a, 0, 'f', 8).arg(hemi);
    case CoordinateFormat::DegreesMinutes: {
        double m = (a - d) * 60; // 6 decimals of a minute: 2 mm, as 8 of a degree
        if (carries(m, 6)) ++d;
        return QStringLiteral("%1° %2′ %3").arg(d).arg(m, 9, 'f', 6, QChar('0')).arg(hemi);
    }
    case CoordinateFormat::DegreesMinutesSeconds: break;
    }
    int m = int((a - d) * 60);
    double s = ((a - d) * 60 - m) * 60;
    if (carries(s, 4) && ++m == 60) m = 0, ++d;
    return QStringLiteral("%1° %2′ %3″ %4")
            .arg(d)
            .arg(m, 2, 10, QChar('0'))
            .arg(s, 7, 'f', 4, QChar('0'))
            .arg(hemi);
}

} // namespace

QString latitude(const std::optional<double> &deg, CoordinateFormat f) {
    return coordinate(deg, f, QT_TRANSLATE_NOOP("Hemisphere", "N"),
                      QT_TRANSLATE_NOOP("Hemisphere", "S"));
}

QString longitude(const std::optional<double> &deg, CoordinateFormat f) {
    return coordinate(deg, f, QT_TRANSLATE_NOOP("Hemisphere", "E"),
                      QT_TRANSLATE_NOOP("Hemisphere", "W"));
}

QString lengthUnit(UnitSystem u) {
    return u == UnitSystem::Imperial ? unitText(QT_TRANSLATE_NOOP("Units", "ft"))
                                     : unitText(QT_TRANSLATE_NOOP("Units", "m"));
}

double lengthFactor(UnitSystem u) {
    return u == UnitSystem::Imperial ? 1.0 / 0.3048 : 1.0;
}

QString length(const std::optional<double> &metres, int decimals, UnitSystem u) {
    if (!metres) return dash();
    return number(*metres * lengthFactor(u), decimals, lengthUnit(u));
}

QString speedUnit(UnitSystem u) {
    switch (u) {
    case UnitSystem::Imperial: return unitText(QT_TRANSLATE_NOOP("Units", "mph"));
    case UnitSystem::Nautical: return unitText(QT_TRANSLATE_NOOP("Units", "kn"));
    case UnitSystem::Metric: break;
    }
    return unitText(QT_TRANSLATE_NOOP("Units", "m/s"));
}

double speedFactor(UnitSystem u) {
    switch (u) {
    case UnitSystem::Imperial: return 3600.0 / 1609.344;
    case UnitSystem::Nautical: return 3600.0 / 1852.0;
    case UnitSystem::Metric: break;
    }
    return 1.0;
}

QString speed(const std::optional<double> &ms, UnitSystem u) {
    if (!ms || !std::isfinite(*ms)) return dash();
    if (u != UnitSystem::Metric) return number(*ms * speedFactor(u), 2, speedUnit(u));
    return QStringLiteral("%1 (%2)").arg(
            number(*ms, 2, speedUnit(u)),
            number(*ms * 3.6, 1, unitText(QT_TRANSLATE_NOOP("Units", "km/h"))));
}

QString distance(const std::optional<double> &metres, int decimals, UnitSystem u) {
    if (!metres) return dash();
    switch (u) {
    case UnitSystem::Imperial:
        return number(*metres / 1609.344, decimals, unitText(QT_TRANSLATE_NOOP("Units", "mi")));
    case UnitSystem::Nautical:
        return number(*metres / 1852.0, decimals, unitText(QT_TRANSLATE_NOOP("Units", "NM")));
    case UnitSystem::Metric: break;
    }
    return number(*metres / 1000.0, decimals, unitText(QT_TRANSLATE_NOOP("Units", "km")));
}

QString hostTime(qint64 ms, TimeZoneChoice zone) {
    const QDateTime at = QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::utc());
    return (zone == TimeZoneChoice::Local ? at.toLocalTime() : at)
            .toString(QStringLiteral("hh:mm:ss.zzz"));
}

QString utcOffset(int offset) {
    return QStringLiteral("UTC%1%2:%3")
            .arg(offset < 0 ? '-' : '+')
            .arg(std::abs(offset) / 3600, 2, 10, QChar('0'))
            .arg(std::abs(offset) / 60 % 60, 2, 10, QChar('0'));
}

QString time(const std::optional<Date> &date, const std::optional<TimeOfDay> &t,
             TimeZoneChoice zone, bool withZone) {
    if (!t) return dash();
    if (zone == TimeZoneChoice::Utc) {
        const std::string s = date ? date->toString() + " " + t->toString(3) : t->toString(3);
        return QString::fromStdString(s) + (withZone ? QStringLiteral(" UTC") : QString());
    }
    const QDate day = date ? QDate(date->year, date->month, date->day)
                           : QDateTime::currentDateTimeUtc().date();
    const qint64 ms = t->nanos / 1'000'000;
    QDateTime utc(day, QTime(0, 0), QTimeZone::utc());
    const QDateTime local = utc.addMSecs(ms).toLocalTime();
    const QString zoneText = utcOffset(local.offsetFromUtc());
    const QString when = local.toString(date ? QStringLiteral("yyyy-MM-dd hh:mm:ss.zzz")
                                             : QStringLiteral("hh:mm:ss.zzz"));
    return withZone ? when + ' ' + zoneText : when;
}

} // namespace fmt
} // namespace gnss::ui
