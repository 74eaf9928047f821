#include "core/field_parse.h"

#include "core/hex_digit.h"

#include <algorithm>
#include <cstdio>

namespace gnss {
namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,
                             1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19};

inline bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// Parses "[+-]digits[.digits]" into an integer mantissa and a count of decimals.
// Returns false on anything else (or more than 18 digits before the point; decimals past the
// 18th significant digit are ignored). A loop for each part: no test per character of which
// part it is in.
inline bool parseDecimal(std::string_view s, bool &neg, std::uint64_t &mant, int &decimals,
                         std::uint64_t &intPart) {
    const char *p = s.data();
    const char *const end = p + s.size();
    neg = false;
    if (p != end && (*p == '-' || *p == '+')) {
        neg = *p == '-';
        ++p;
    }
    mant = 0;
    decimals = 0;
    unsigned d;
    const char *const whole = p;
    for (; p != end && (d = static_cast<unsigned char>(*p) - '0') <= 9; ++p) mant = mant * 10 + d;
    int digits = static_cast<int>(p - whole);
    if (digits > 18) return false;
    intPart = mant;
    if (p != end && *p == '.') {
        for (++p; p != end && (d = static_cast<unsigned char>(*p) - '0') <= 9; ++p) {
            if (digits >= 18) continue; // extra precision beyond double's: ignore
            ++digits;
            mant = mant * 10 + d;
            ++decimals;
        }
    }
    return digits > 0 && p == end;
}

} // namespace

bool parseReal(std::string_view s, double &out) {
    // Fast path: unsigned "digits[.digits]" with at most 15 significant digits, the form of
    // nearly every real field (DOPs, altitudes, speeds); exact to the last digit. Two plain
    // loops, the whole part then the decimals: no test per character of which part it is in.
    if (s.size() - 1 < 16) {
        const char *p = s.data();
        const char *const end = p + s.size();
        std::uint64_t mant = 0;
        unsigned d;
        for (; p != end && (d = static_cast<unsigned char>(*p) - '0') <= 9; ++p)
            mant = mant * 10 + d;
        const bool whole = p != s.data();
        int dec = 0;
        if (p != end && *p == '.') {
            const char *const first = ++p;
            for (; p != end && (d = static_cast<unsigned char>(*p) - '0') <= 9; ++p)
                mant = mant * 10 + d;
            dec = static_cast<int>(p - first);
        }
        if (p == end && (whole || dec > 0)) {
            out = dec > 0 ? static_cast<double>(mant) / kPow10[dec] : static_cast<double>(mant);
            return true;
        }
    }
    bool neg;
    std::uint64_t mant, intPart;
    int dec;
    if (!parseDecimal(s, neg, mant, dec, intPart)) return false;
    double v = static_cast<double>(mant) / kPow10[dec];
    out = neg ? -v : v;
    return true;
}

bool parseInt(std::string_view s, std::int64_t &out) {
    std::size_t i = 0;
    bool neg = false;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) {
        neg = s[i] == '-';
        ++i;
    }
    if (i == s.size() || s.size() - i > 18) return false;
    std::int64_t v = 0;
    for (; i < s.size(); ++i) {
        if (!isDigit(s[i])) return false;
        v = v * 10 + (s[i] - '0');
    }
    out = neg ? -v : v;
    return true;
}

bool parseHex(std::string_view s, std::uint64_t &out) {
    if (s.empty() || s.size() > 16) return false;
    std::uint64_t v = 0;
    for (char c : s) {
        const int d = hexDigitValue(c);
        if (d < 0) return false;
        v = (v << 4) | static_cast<std::uint64_t>(d);
    }
    out = v;
    return true;
}

bool parseDegreesMinutes(std::string_view s, int maxDegrees, double &out) {
    bool neg;
    std::uint64_t mant, intPart;
    int dec;
    if (!parseDecimal(s, neg, mant, dec, intPart) || neg) return false;
    const std::uint64_t degrees = intPart / 100;
    // Minutes = (intPart % 100) + fraction, computed from the exact mantissa.
    const std::uint64_t scale = static_cast<std::uint64_t>(kPow10[dec]);
    const std::uint64_t minutesScaled = mant - degrees * 100 * scale;
    const double minutes = static_cast<double>(minutesScaled) / kPow10[dec];
    if (minutes >= 60.0 || degrees > static_cast<std::uint64_t>(maxDegrees)) return false;
    out = static_cast<double>(degrees) + minutes / 60.0;
    if (out > maxDegrees) return false;
    return true;
}

bool parseTimeOfDay(std::string_view s, TimeOfDay &out) {
    if (s.size() < 6) return false;
    for (int i = 0; i < 6; ++i)
        if (!isDigit(s[i])) return false;
    const int h = (s[0] - '0') * 10 + (s[1] - '0');
    const int m = (s[2] - '0') * 10 + (s[3] - '0');
    const int sec = (s[4] - '0') * 10 + (s[5] - '0');
    if (h > 23 || m > 59 || sec > 60 || (sec == 60 && (h != 23 || m != 59)))
        return false; // leap second only at 23:59:60
    std::int64_t frac = 0;
    int dec = 0;
    if (s.size() > 6) {
        if (s[6] != '.') return false;
        for (std::size_t i = 7; i < s.size(); ++i) {
            if (!isDigit(s[i])) return false;
            if (dec < 9) {
                frac = frac * 10 + (s[i] - '0');
                ++dec;
            }
        }
    }
    static constexpr std::int64_t kScale[] = {1000000000, 100000000, 10000000, 1000000, 100000,
                                              10000,      1000,      100,      10,      1};
    out.nanos = ((h * 60LL + m) * 60LL + sec) * 1'000'000'000LL + frac * kScale[dec];
    out.decimals = static_cast<std::uint8_t>(dec);
    return true;
}

bool parseDateDdMmYy(std::string_view s, Date &out) {
    if (s.size() != 6) return false;
    for (char c : s)
        if (!isDigit(c)) return false;
    const int d = (s[0] - '0') * 10 + (s[1] - '0');
    const int mo = (s[2] - '0') * 10 + (s[3] - '0');
    const int y = (s[4] - '0') * 10 + (s[5] - '0');
    if (d < 1 || d > 31 || mo < 1 || mo > 12) return false;
    out.day = d;
    out.month = mo;
    out.year = y >= 80 ? 1900 + y : 2000 + y;
    return true;
}

std::string TimeOfDay::toString(int minDecimals) const {
    // Nanoseconds are all there is: more than 9 decimals would print a wrong fraction.
    const int dec = std::clamp(decimals > minDecimals ? decimals : minDecimals, 0, 9);
    char buf[48];
    // A leap second (23:59:60) is stored past the end of the day.
    const bool leap = nanos >= 86'400'000'000'000LL;
    const std::int64_t secNanos = leap ? nanos - 86'340'000'000'000LL : nanos % 60'000'000'000LL;
    const int hh = leap ? 23 : hour(), mm = leap ? 59 : minute();
    const long long whole = secNanos / 1'000'000'000LL;
    long long frac = secNanos % 1'000'000'000LL;
    for (int i = dec; i < 9; ++i) frac /= 10;
    const int n = std::snprintf(buf, sizeof buf, "%02d:%02d:%02lld", hh, mm, whole);
    std::string out(buf, static_cast<std::size_t>(std::clamp(n, 0, int(sizeof buf) - 1)));
    if (dec > 0) { // the decimals digit by digit: a "%0*lld" of variable width made GCC warn
        out.push_back('.');
        out.resize(out.size() + static_cast<std::size_t>(dec));
        char *digit = out.data() + out.size();
        for (int i = 0; i < dec; ++i, frac /= 10) *--digit = static_cast<char>('0' + frac % 10);
    }
    return out;
}

std::string Date::toString() const {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", year, month, day);
    return buf;
}

} // namespace gnss
