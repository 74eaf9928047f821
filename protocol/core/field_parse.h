#pragma once
// Field parsers: text → numbers, coordinates, times, dates. No allocation, no exceptions, no
// locale: these run for every field of every sentence.
#include "field_types.h"

#include <cstdint>
#include <string_view>

namespace gnss {

bool parseReal(std::string_view s, double &out);
bool parseInt(std::string_view s, std::int64_t &out);
bool parseHex(std::string_view s, std::uint64_t &out);
// NMEA "ddmm.mmmm" / "dddmm.mmmm" → degrees (unsigned); maxDegrees is 90 or 180.
bool parseDegreesMinutes(std::string_view s, int maxDegrees, double &out);
// "hhmmss" or "hhmmss.sss…" (up to 9 decimals).
bool parseTimeOfDay(std::string_view s, TimeOfDay &out);
// "ddmmyy": two-digit years pivot at 1980 (80-99 → 19xx).
bool parseDateDdMmYy(std::string_view s, Date &out);

} // namespace gnss
