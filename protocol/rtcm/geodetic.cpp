#include "geodetic.h"

#include <cmath>
#include <numbers>

namespace gnss::rtcm {
namespace {
constexpr double kE2 = kWgs84F * (2.0 - kWgs84F); // first eccentricity squared
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
} // namespace

// The ellipsoid normal through p meets the polar axis at z = −N e² sin φ; seen from there p lies
// at elevation φ, so φ = atan2(z + N e² sin φ, ρ) and N + h is the distance between the two.
// Iterating on z' = z + N e² sin φ shrinks the error by about e² (0.0067) a step anywhere outside
// the Earth's core, poles included (nothing is divided by cos φ): a few steps reach the last bit.
std::optional<Geodetic> ecefToGeodetic(const Ecef &p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
    const double r2 = p.x * p.x + p.y * p.y;
    if (r2 + p.z * p.z < 1.0) return std::nullopt;
    const double rho = std::sqrt(r2);
    double zp = p.z;
    double n = kWgs84A;
    for (int i = 0; i < 30; ++i) {
        const double sinPhi = zp / std::sqrt(r2 + zp * zp);
        n = kWgs84A / std::sqrt(1.0 - kE2 * sinPhi * sinPhi);
        const double next = p.z + n * kE2 * sinPhi;
        const bool done = std::fabs(next - zp) < 1e-10;
        zp = next;
        if (done) break;
    }
    const double sinPhi = zp / std::sqrt(r2 + zp * zp);
    n = kWgs84A / std::sqrt(1.0 - kE2 * sinPhi * sinPhi);
    Geodetic g;
    g.latDeg = std::atan2(zp, rho) * kRadToDeg;
    g.lonDeg = r2 > 0 ? std::atan2(p.y, p.x) * kRadToDeg : 0.0;
    g.height = std::sqrt(r2 + zp * zp) - n;
    return g;
}

Ecef geodeticToEcef(const Geodetic &g) {
    const double lat = g.latDeg / kRadToDeg;
    const double lon = g.lonDeg / kRadToDeg;
    const double sinLat = std::sin(lat);
    const double n = kWgs84A / std::sqrt(1.0 - kE2 * sinLat * sinLat);
    const double c = (n + g.height) * std::cos(lat);
    return {c * std::cos(lon), c * std::sin(lon), (n * (1.0 - kE2) + g.height) * sinLat};
}

} // namespace gnss::rtcm
