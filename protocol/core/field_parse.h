#pragma once
// Field parsers: text → numbers, coordinates, times, dates. No allocation, no exceptions, no
// locale: these run for every field of every sentence.
#include "field_types.h"

#include <cstdint>
#include <string_view>

namespace gnss {

bool parseReal(std::string_view s, double &out);

// Inline fast path for the most common field: a short optionally signed decimal integer
// ("08", "-2", "115200"). Returns false for anything else, including values beyond 9 digits.
inline bool parseSmallInt(std::string_view s, int &out) {
    const char *p = s.data();
    const std::size_t n = s.size();
    if (n == 0 || n > 10) return false;
    unsigned d = static_cast<unsigned char>(*p) - '0';
    if (d <= 9) { // common case: no sign
        if (n > 9) return false;
        int v = static_cast<int>(d);
        for (std::size_t i = 1; i < n; ++i) {
            d = static_cast<unsigned char>(p[i]) - '0';
            if (d > 9) return false;
            v = v * 10 + static_cast<int>(d);
        }
        out = v;
        return true;
    }
    if ((*p != '-' && *p != '+') || n == 1) return false;
    int v = 0;
    for (std::size_t i = 1; i < n; ++i) {
        d = static_cast<unsigned char>(p[i]) - '0';
        if (d > 9) return false;
        v = v * 10 + static_cast<int>(d);
    }
    out = *p == '-' ? -v : v;
    return true;
}
bool parseInt(std::string_view s, std::int64_t &out);
bool parseHex(std::string_view s, std::uint64_t &out);
// NMEA "ddmm.mmmm" / "dddmm.mmmm" → degrees (unsigned); maxDegrees is 90 or 180.
bool parseDegreesMinutes(std::string_view s, int maxDegrees, double &out);
// "hhmmss" or "hhmmss.sss…" (up to 9 decimals).
bool parseTimeOfDay(std::string_view s, TimeOfDay &out);
// "ddmmyy": two-digit years pivot at 1980 (80-99 → 19xx).
bool parseDateDdMmYy(std::string_view s, Date &out);

} // namespace gnss
