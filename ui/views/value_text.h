#pragma once
// Value text for the panels, following UI.md "Numbers and units": "—" for a value the receiver
// has not sent (never 0), hemispheres instead of a minus sign, UTC with milliseconds.
#include "core/field_types.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace gnss::ui::text {

// The one placeholder for a missing value.
QString dash();

// "1.234 m" (value, fixed decimals, optional unit after a space), or "—".
QString number(std::optional<double> v, int decimals, const QString &unit = {});
QString integer(std::optional<std::int64_t> v, const QString &unit = {});
// Decimal degrees with hemisphere: "47.40853048° N" / "9.62826005° E" (8 decimals by default).
QString latitude(std::optional<double> deg, int decimals = 8);
QString longitude(std::optional<double> deg, int decimals = 8);
// "hh:mm:ss.sss" UTC, or "—".
QString utcTime(const std::optional<TimeOfDay> &t);

} // namespace gnss::ui::text
