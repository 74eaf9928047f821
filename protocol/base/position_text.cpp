#include "base/position_text.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace gnss::base {

namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool isNumberChar(char c) {
    return (c >= '0' && c <= '9') || c == '.';
}

// Separators between degrees, minutes and seconds: space, ':', d m s, ' " and their typographic
// forms (°, ′, ″, ’, ”: UTF-8 sequences).
std::size_t separatorLength(std::string_view s) {
    static constexpr std::string_view kMulti[] = {"\xC2\xB0", "\xE2\x80\xB2", "\xE2\x80\xB3",
                                                  "\xE2\x80\x99", "\xE2\x80\x9D"};
    for (std::string_view m : kMulti)
        if (s.starts_with(m)) return m.size();
    const char c = s.front();
    if (c == ' ' || c == ':' || c == '\'' || c == '"' || c == 'd' || c == 'm' || c == 's') return 1;
    return 0;
}

} // namespace

std::optional<double> parseAngle(std::string_view text, Axis axis, std::string &error) {
    const char *what = axis == Axis::Latitude ? "latitude" : "longitude";
    // Capitals only: a lower-case s is the seconds' mark ("4.32s").
    const std::string_view positive = axis == Axis::Latitude ? "N" : "E";
    const std::string_view negative = axis == Axis::Latitude ? "S" : "W";
    const std::string_view other = axis == Axis::Latitude ? "EW" : "NS";
    std::string_view s = trimmed(text);
    auto fail = [&](const std::string &why) -> std::optional<double> {
        error = std::string(what) + ": " + why;
        return std::nullopt;
    };
    if (s.empty()) return fail("empty");
    int sign = 1;
    bool hemisphere = false;
    auto takeHemisphere = [&](char c) {
        if (positive.find(c) != std::string_view::npos) return hemisphere = true, true;
        if (negative.find(c) != std::string_view::npos) return sign = -1, hemisphere = true, true;
        return false;
    };
    if (other.find(s.front()) != std::string_view::npos ||
        other.find(s.back()) != std::string_view::npos)
        return fail("'" + std::string(text) + "' names the other axis's hemisphere");
    if (takeHemisphere(s.front()))
        s = trimmed(s.substr(1));
    else if (!s.empty() && takeHemisphere(s.back()))
        s = trimmed(s.substr(0, s.size() - 1));
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
        if (hemisphere) return fail("a sign and a hemisphere letter together");
        if (s.front() == '-') sign = -1;
        s.remove_prefix(1);
    }
    std::vector<double> parts;
    std::vector<bool> fractional;
    while (!s.empty()) {
        if (const std::size_t n = separatorLength(s)) {
            s.remove_prefix(n);
            continue;
        }
        if (!isNumberChar(s.front()))
            return fail("'" + std::string(text) + "' is not an angle (degrees, DM or DMS)");
        std::size_t n = 0;
        while (n < s.size() && isNumberChar(s[n])) ++n;
        double v = 0;
        const auto r = std::from_chars(s.data(), s.data() + n, v);
        if (r.ec != std::errc() || r.ptr != s.data() + n)
            return fail("'" + std::string(s.substr(0, n)) + "' is not a number");
        parts.push_back(v);
        fractional.push_back(s.substr(0, n).find('.') != std::string_view::npos);
        s.remove_prefix(n);
    }
    if (parts.empty() || parts.size() > 3) return fail("expected degrees, minutes, seconds");
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        if (fractional[i]) return fail("only the last of degrees, minutes, seconds has decimals");
    if (parts.size() >= 2 && parts[1] >= 60)
        return fail("minutes " + std::to_string(int(parts[1])) + " are not below 60");
    if (parts.size() == 3 && parts[2] >= 60)
        return fail("seconds " + std::to_string(int(parts[2])) + " are not below 60");
    double deg = parts[0];
    if (parts.size() >= 2) deg += parts[1] / 60;
    if (parts.size() == 3) deg += parts[2] / 3600;
    const double limit = axis == Axis::Latitude ? 90 : 180;
    if (!std::isfinite(deg) || deg > limit)
        return fail("'" + std::string(text) + "' is beyond " + std::to_string(int(limit)) + "°");
    return sign * deg;
}

std::optional<wgs84::Geodetic> parseGeodetic(std::string_view text, std::string &error) {
    std::vector<std::string_view> fields;
    std::size_t at = 0;
    while (true) {
        const std::size_t comma = text.find(',', at);
        fields.push_back(text.substr(at, comma == std::string_view::npos ? text.npos : comma - at));
        if (comma == std::string_view::npos) break;
        at = comma + 1;
    }
    if (fields.size() != 3) {
        error = "expected LAT,LON,HEIGHT (degrees, degrees, metres), got '" + std::string(text) +
                "'";
        return std::nullopt;
    }
    const auto lat = parseAngle(fields[0], Axis::Latitude, error);
    if (!lat) return std::nullopt;
    const auto lon = parseAngle(fields[1], Axis::Longitude, error);
    if (!lon) return std::nullopt;
    const std::string_view h = trimmed(fields[2]);
    double height = 0;
    const auto r = std::from_chars(h.data(), h.data() + h.size(), height);
    if (h.empty() || r.ec != std::errc() || r.ptr != h.data() + h.size() ||
        !std::isfinite(height) || std::abs(height) > 100000) {
        error = "height: '" + std::string(h) + "' is not metres (-100000 to 100000)";
        return std::nullopt;
    }
    return wgs84::Geodetic{*lat, *lon, height};
}

} // namespace gnss::base
