#include "ntrip/mountpoint_distance.h"

#include "core/wgs84.h"

#include <algorithm>
#include <cmath>

namespace gnss::ntrip {

double greatCircleMetres(double lat1Deg, double lon1Deg, double lat2Deg, double lon2Deg) {
    constexpr double kDeg = wgs84::kDegree;
    const double phi1 = lat1Deg * kDeg, phi2 = lat2Deg * kDeg;
    const double dPhi = phi2 - phi1, dLambda = (lon2Deg - lon1Deg) * kDeg;
    const double a = std::sin(dPhi / 2) * std::sin(dPhi / 2) + std::cos(phi1) * std::cos(phi2) *
                                                                       std::sin(dLambda / 2) *
                                                                       std::sin(dLambda / 2);
    // Clamped: rounding can push a above 1 for antipodal points.
    return 2 * wgs84::kMeanRadius * std::asin(std::sqrt(std::clamp(a, 0.0, 1.0)));
}

std::optional<std::pair<double, double>> entryPosition(const StreamEntry &s) {
    if (!s.latitude || !s.longitude) return std::nullopt;
    if (*s.latitude == 0 && *s.longitude == 0) return std::nullopt;
    return std::make_pair(*s.latitude, *s.longitude);
}

NearestChoice nearestMountpoint(const SourceTable &table, double latDeg, double lonDeg,
                                const NearestOptions &options) {
    NearestChoice best;
    if (!std::isfinite(latDeg) || !std::isfinite(lonDeg)) return best;
    for (const StreamEntry &s : table.streams) {
        if (options.rtcm3Only && !isRtcm3Format(s.format)) continue;
        if (options.onlyWantingGga && !s.wantsGga) continue;
        const auto pos = entryPosition(s);
        if (!pos) continue;
        const double d = greatCircleMetres(latDeg, lonDeg, pos->first, pos->second);
        if (!best.entry || d < best.distanceMetres) best = {&s, d};
    }
    return best;
}

} // namespace gnss::ntrip
