#pragma once
// Field parsers: text → numbers, coordinates, times, dates. No allocation, no exceptions, no
// locale: these run for every field of every sentence.
#include "core/field_types.h"

#include <cstdint>
#include <string_view>

namespace gnss {

bool parseReal(std::string_view s, double &out);

// Inline fast path for the most common field: a short optionally signed decimal integer
// ("08", "-2", "115200"). Returns false for anything else, including values beyond 9 digits.
inline bool parseSmallInt(std::string_view s, int &out) {
    const auto *p = reinterpret_cast<const unsigned char *>(s.data());
    const std::size_t n = s.size();
    // One to three digits (ids, elevations, azimuths, SNRs, counts): straight-line code.
    switch (n) {
    case 1: {
        const unsigned a = p[0] - '0';
        if (a > 9) return false;
        out = static_cast<int>(a);
        return true;
    }
    case 2: {
        const unsigned a = p[0] - '0', b = p[1] - '0';
        if (a > 9 || b > 9) break; // may be "-2"
        out = static_cast<int>(a * 10 + b);
        return true;
    }
    case 3: {
        const unsigned a = p[0] - '0', b = p[1] - '0', c = p[2] - '0';
        if (a > 9 || b > 9 || c > 9) break;
        out = static_cast<int>(a * 100 + b * 10 + c);
        return true;
    }
    default:
        if (n == 0 || n > 10) return false;
    }
    std::size_t i = 0;
    bool neg = false;
    if (p[0] == '-' || p[0] == '+') {
        neg = p[0] == '-';
        i = 1;
        if (n == 1) return false;
    }
    if (n - i > 9) return false;
    int v = 0;
    for (; i < n; ++i) {
        const unsigned d = p[i] - '0';
        if (d > 9) return false;
        v = v * 10 + static_cast<int>(d);
    }
    out = neg ? -v : v;
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
