#pragma once
// Number formatting shared by the panels, the same rules in every one: "—" for a value the
// receiver has not sent, hemispheres instead of signs, units always said, and the user's
// display preferences (units, coordinate format, time zone) applied in one place.
#include <QString>
#include <cstdint>
#include <optional>

namespace gnss {
struct Date;
struct TimeOfDay;
} // namespace gnss

namespace gnss::ui {

enum class UnitSystem : quint8 {
    Metric,   // m, m/s and km/h, km
    Imperial, // ft, mph, mi
    Nautical, // m, kn, NM
};
enum class CoordinateFormat : quint8 {
    Degrees,               // 55.84338247° N
    DegreesMinutes,        // 55° 50.602948′ N
    DegreesMinutesSeconds, // 55° 50′ 36.1769″ N
};
enum class TimeZoneChoice : quint8 { Utc, Local };

// How the views show numbers; the preferences dialog edits it, the main window hands it to
// every view (setDisplayPrefs).
struct DisplayPrefs {
    UnitSystem units = UnitSystem::Metric;
    CoordinateFormat coordinates = CoordinateFormat::Degrees;
    TimeZoneChoice time = TimeZoneChoice::Utc;
    bool operator==(const DisplayPrefs &) const = default;
};
// "metric"/"imperial"/"nautical", "deg"/"dm"/"dms", "utc"/"local" (QSettings, options); the
// parse functions keep `fallback` for an unknown text.
QString toKey(UnitSystem u);
QString toKey(CoordinateFormat c);
QString toKey(TimeZoneChoice t);
UnitSystem unitSystemFromKey(const QString &key, UnitSystem fallback = UnitSystem::Metric);
CoordinateFormat coordinateFormatFromKey(const QString &key,
                                         CoordinateFormat fallback = CoordinateFormat::Degrees);
TimeZoneChoice timeZoneFromKey(const QString &key, TimeZoneChoice fallback = TimeZoneChoice::Utc);

namespace fmt {

QString dash();
QString number(const std::optional<double> &v, int decimals, const QString &unit = {});
QString integer(const std::optional<int> &v, const QString &unit = {});
// A counter, which can pass an int's range.
QString count(const std::optional<std::int64_t> &v);
// An angle in degrees, "40.61°": no space before the degree sign.
QString angle(const std::optional<double> &degrees, int decimals);
// 55.84338247° N  |  55° 50.602948′ N  |  55° 50′ 36.1769″ N
QString latitude(const std::optional<double> &deg, CoordinateFormat f = CoordinateFormat::Degrees);
QString longitude(const std::optional<double> &deg, CoordinateFormat f = CoordinateFormat::Degrees);

// A length given in metres (heights, offsets, baselines, deviations): m, or ft when imperial.
QString length(const std::optional<double> &metres, int decimals, UnitSystem u);
// The unit length() writes, and the factor from metres to it.
QString lengthUnit(UnitSystem u);
double lengthFactor(UnitSystem u);
// A speed given in m/s: "1.25 m/s (4.5 km/h)", "2.80 mph", "2.43 kn".
QString speed(const std::optional<double> &metresPerSecond, UnitSystem u);
QString speedUnit(UnitSystem u);  // m/s, mph, kn
double speedFactor(UnitSystem u); // from m/s
// A long distance given in metres: km, mi or NM.
QString distance(const std::optional<double> &metres, int decimals, UnitSystem u);
// The receiver's UTC date (may be absent) and time: "2026-12-01 05:46:15.250 UTC", or local
// time with its offset "2026-12-01 08:46:15.250 UTC+03:00" (today's date when the receiver
// sends none). Without the zone's name when `withZone` is false (a table column that says it).
// A host clock reading (ms since the epoch) as "hh:mm:ss.zzz", in UTC or local time.
QString hostTime(qint64 msSinceEpoch, TimeZoneChoice zone);
// "UTC+03:00" for an offset from UTC in seconds.
QString utcOffset(int seconds);
QString time(const std::optional<Date> &date, const std::optional<TimeOfDay> &time,
             TimeZoneChoice zone, bool withZone = true);

} // namespace fmt
} // namespace gnss::ui
