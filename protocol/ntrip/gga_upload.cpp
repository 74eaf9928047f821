#include "ntrip/gga_upload.h"

#include "core/sentence_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::ntrip {

namespace {

// Degrees as NMEA's [d]ddmm.mmmmm, rounded once on the whole value so 59.999996' becomes the
// next degree rather than "60.00000".
std::string degreesMinutes(double deg, int degreeDigits) {
    const auto units = static_cast<std::int64_t>(std::llround(std::fabs(deg) * 60.0 * 1e5));
    const std::int64_t perDegree = 60 * 100000;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*lld%02lld.%05lld", degreeDigits,
                  static_cast<long long>(units / perDegree),
                  static_cast<long long>(units % perDegree / 100000),
                  static_cast<long long>(units % 100000));
    return buf;
}

} // namespace

std::string buildGga(const GgaPosition &p, std::int64_t utcMsOfDay) {
    constexpr std::int64_t kDayMs = 86400000;
    std::int64_t ms = utcMsOfDay % kDayMs;
    if (ms < 0) ms += kDayMs;
    const std::int64_t cs = ms / 10; // hundredths of a second
    char time[16];
    std::snprintf(time, sizeof time, "%02lld%02lld%02lld.%02lld",
                  static_cast<long long>(cs / 360000), static_cast<long long>(cs / 6000 % 60),
                  static_cast<long long>(cs / 100 % 60), static_cast<long long>(cs % 100));

    std::string body = "GPGGA,";
    body += time;
    const bool valid = std::isfinite(p.latDeg) && std::isfinite(p.lonDeg) &&
                       std::isfinite(p.altitudeMsl) && std::isfinite(p.geoidSeparation);
    if (!valid) {
        body += ",,,,,0,00,,,M,,M,,";
        return buildSentence(body);
    }
    const double lat = std::clamp(p.latDeg, -90.0, 90.0);
    double lon = std::fmod(p.lonDeg, 360.0);
    if (lon >= 180) lon -= 360;
    if (lon < -180) lon += 360;
    char tail[96];
    const double hdop = std::isfinite(p.hdop) ? std::clamp(p.hdop, 0.0, 99.9) : 99.9;
    std::snprintf(tail, sizeof tail, ",%d,%02d,%s,%s,M,%s,M,,", std::clamp(p.quality, 0, 9),
                  std::clamp(p.satellites, 0, 99), formatFixed(hdop, 1).c_str(),
                  formatFixed(p.altitudeMsl, 3).c_str(), formatFixed(p.geoidSeparation, 3).c_str());
    body += ",";
    body += degreesMinutes(lat, 2);
    body += lat < 0 ? ",S," : ",N,";
    body += degreesMinutes(lon, 3);
    body += lon < 0 ? ",W" : ",E";
    body += tail;
    return buildSentence(body);
}

} // namespace gnss::ntrip
