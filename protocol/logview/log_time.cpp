#include "logview/log_time.h"

#include "logview/epoch_runner.h"

#include <charconv>
#include <cstdio>

namespace gnss::logview {
namespace {

bool digits(std::string_view s, std::size_t pos, std::size_t n, int &out) {
    if (pos + n > s.size()) return false;
    out = 0;
    for (std::size_t i = pos; i < pos + n; ++i) {
        if (s[i] < '0' || s[i] > '9') return false;
        out = out * 10 + (s[i] - '0');
    }
    return true;
}

// "hh:mm[:ss[.fff]]" or "h:mm…" (as people write "9:42") → ms; nullopt when it is not one.
std::optional<std::int64_t> timeOfDay(std::string_view s) {
    int h = 0, m = 0, sec = 0;
    const std::size_t hourDigits = s.size() > 1 && s[1] == ':' ? 1 : 2;
    if (!digits(s, 0, hourDigits, h) || s.size() < hourDigits + 3 || s[hourDigits] != ':' ||
        !digits(s, hourDigits + 1, 2, m))
        return {};
    std::size_t pos = hourDigits + 3;
    double frac = 0;
    if (pos < s.size() && s[pos] == ':') {
        if (!digits(s, pos + 1, 2, sec)) return {};
        pos += 3;
        if (pos < s.size() && s[pos] == '.') {
            double scale = 0.1;
            ++pos;
            while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') {
                frac += (s[pos] - '0') * scale;
                scale /= 10;
                ++pos;
            }
        }
    }
    if (pos < s.size() && (s[pos] == 'Z' || s[pos] == 'z')) ++pos;
    if (pos != s.size() || h > 23 || m > 59 || sec > 60) return {};
    return (h * 3600 + m * 60 + sec) * 1000LL + static_cast<std::int64_t>(frac * 1000 + 0.5);
}

} // namespace

std::optional<TimeSpec> parseTimeSpec(std::string_view s) {
    TimeSpec t;
    if (!s.empty() && s[0] == '#') {
        t.kind = TimeSpec::Kind::Epoch;
        const auto r = std::from_chars(s.data() + 1, s.data() + s.size(), t.epoch);
        if (r.ec != std::errc() || r.ptr != s.data() + s.size() || s.size() < 2) return {};
        return t;
    }
    int y = 0, mo = 0, d = 0;
    if (s.size() >= 10 && digits(s, 0, 4, y) && s[4] == '-' && digits(s, 5, 2, mo) && s[7] == '-' &&
        digits(s, 8, 2, d)) {
        if (mo < 1 || mo > 12 || d < 1 || d > 31) return {};
        std::int64_t ms = 0;
        if (s.size() > 10) {
            if (s[10] != 'T' && s[10] != ' ' && s[10] != 't') return {};
            const auto tod = timeOfDay(s.substr(11));
            if (!tod) return {};
            ms = *tod;
        }
        t.kind = TimeSpec::Kind::Utc;
        t.ms = daysFromCivil(y, mo, d) * 86'400'000 + ms;
        return t;
    }
    const auto tod = timeOfDay(s);
    if (!tod) return {};
    t.kind = TimeSpec::Kind::TimeOfDay;
    t.ms = *tod;
    return t;
}

std::string formatUtcMs(std::int64_t ms) {
    std::int64_t days = ms >= 0 ? ms / 86'400'000 : -((-ms + 86'399'999) / 86'400'000);
    std::int64_t rest = ms - days * 86'400'000;
    // Civil date from days (inverse of daysFromCivil).
    days += 719468;
    const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
    const unsigned doe = static_cast<unsigned>(days - era * 146097);
    const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const std::int64_t y0 = static_cast<std::int64_t>(yoe) + era * 400;
    const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const unsigned mp = (5 * doy + 2) / 153;
    const unsigned d = doy - (153 * mp + 2) / 5 + 1;
    const unsigned m = mp < 10 ? mp + 3 : mp - 9;
    const std::int64_t y = y0 + (m <= 2);
    char b[64];
    std::snprintf(b, sizeof b, "%04lld-%02u-%02uT%02lld:%02lld:%02lld.%03lldZ",
                  static_cast<long long>(y), m, d, static_cast<long long>(rest / 3'600'000),
                  static_cast<long long>(rest / 60'000 % 60),
                  static_cast<long long>(rest / 1000 % 60), static_cast<long long>(rest % 1000));
    return b;
}

std::string formatTime(const EpochRecord &r) {
    if (!r.hasTime()) return {};
    if (r.has(kDateKnown)) return formatUtcMs(r.utcMs);
    const std::int64_t day = r.utcMs / 86'400'000, ms = r.utcMs % 86'400'000;
    char b[64];
    std::snprintf(b, sizeof b, "%02lld:%02lld:%02lld.%03lld",
                  static_cast<long long>(ms / 3'600'000), static_cast<long long>(ms / 60'000 % 60),
                  static_cast<long long>(ms / 1000 % 60), static_cast<long long>(ms % 1000));
    std::string out = b;
    if (day > 0) out += "+" + std::to_string(day) + "d";
    return out;
}

std::string_view fixWords(FixType f) {
    switch (f) {
    case FixType::None: return "no fix";
    case FixType::Estimated: return "estimated";
    case FixType::Fix2D: return "2D";
    case FixType::Fix3D: return "3D";
    case FixType::Dgnss: return "DGNSS";
    case FixType::RtkFloat: return "RTK float";
    case FixType::RtkFixed: return "RTK fixed";
    case FixType::Manual: return "fixed position";
    case FixType::Simulator: return "simulator";
    }
    return "no fix";
}

} // namespace gnss::logview
