#include "core/wgs84.h"

#include <cmath>
#include <numbers>

namespace gnss::wgs84 {

static_assert(kPi == std::numbers::pi);

Ecef toEcef(const Geodetic &g) {
    const double lat = radians(g.latDeg), lon = radians(g.lonDeg);
    const double sinLat = std::sin(lat);
    const double n = kA / std::sqrt(1.0 - kE2 * sinLat * sinLat); // prime vertical radius
    const double c = (n + g.height) * std::cos(lat);
    return {c * std::cos(lon), c * std::sin(lon), (n * (1.0 - kE2) + g.height) * sinLat};
}

// The ellipsoid normal through p meets the polar axis at z = -N e² sin φ; seen from there p lies
// at elevation φ, so φ = atan2(z + N e² sin φ, ρ) and N + h is the distance between the two.
// Iterating on z' = z + N e² sin φ shrinks the error by about e² (0.0067) a step anywhere outside
// the Earth's core, poles included (nothing is divided by cos φ): a few steps reach the last bit.
std::optional<Geodetic> toGeodetic(const Ecef &p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
    const double r2 = p.x * p.x + p.y * p.y;
    if (r2 + p.z * p.z < 1.0) return std::nullopt;
    const double rho = std::sqrt(r2);
    double zp = p.z;
    for (int i = 0; i < 30; ++i) {
        const double sinPhi = zp / std::sqrt(r2 + zp * zp);
        const double n = kA / std::sqrt(1.0 - kE2 * sinPhi * sinPhi);
        const double next = p.z + n * kE2 * sinPhi;
        const bool done = std::fabs(next - zp) < 1e-10;
        zp = next;
        if (done) break;
    }
    const double sinPhi = zp / std::sqrt(r2 + zp * zp);
    const double n = kA / std::sqrt(1.0 - kE2 * sinPhi * sinPhi);
    Geodetic g;
    g.latDeg = degrees(std::atan2(zp, rho));
    g.lonDeg = r2 > 0 ? degrees(std::atan2(p.y, p.x)) : 0.0;
    g.height = std::sqrt(r2 + zp * zp) - n;
    return g;
}

MetresPerDegree metresPerDegree(double latDeg) {
    const double sinPhi = std::sin(radians(latDeg));
    const double w = std::sqrt(1.0 - kE2 * sinPhi * sinPhi);
    return {kA * (1.0 - kE2) / (w * w * w) * kDegree,      // meridian radius
            kA / w * std::cos(radians(latDeg)) * kDegree}; // parallel radius
}

} // namespace gnss::wgs84
