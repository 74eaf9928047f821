#include "geodesy.h"

#include <cmath>
#include <numbers>

namespace gnss::config {

namespace {
constexpr double kE2 = kWgs84F * (2 - kWgs84F); // first eccentricity squared
constexpr double kB = kWgs84A * (1 - kWgs84F);  // semi-minor axis
} // namespace

double degrees(double r) {
    return r * 180.0 / std::numbers::pi;
}
double radians(double d) {
    return d * std::numbers::pi / 180.0;
}

Ecef toEcef(const Geodetic &g) {
    const double s = std::sin(g.lat), c = std::cos(g.lat);
    const double n = kWgs84A / std::sqrt(1 - kE2 * s * s); // prime vertical radius
    return {(n + g.height) * c * std::cos(g.lon), (n + g.height) * c * std::sin(g.lon),
            (n * (1 - kE2) + g.height) * s};
}

Geodetic toGeodetic(const Ecef &e) {
    Geodetic g;
    const double p = std::hypot(e.x, e.y);
    g.lon = std::atan2(e.y, e.x);
    if (p < 1e-9) { // on the axis
        g.lat = e.z >= 0 ? std::numbers::pi / 2 : -std::numbers::pi / 2;
        g.height = std::fabs(e.z) - kB;
        return g;
    }
    // Bowring's starting value, then Newton-like refinement of latitude and height.
    const double ep2 = kE2 / (1 - kE2);
    const double theta = std::atan2(e.z * kWgs84A, p * kB);
    const double st = std::sin(theta), ct = std::cos(theta);
    double lat = std::atan2(e.z + ep2 * kB * st * st * st, p - kE2 * kWgs84A * ct * ct * ct);
    double h = 0;
    for (int i = 0; i < 5; ++i) {
        const double s = std::sin(lat);
        const double n = kWgs84A / std::sqrt(1 - kE2 * s * s);
        h = p / std::cos(lat) - n;
        if (std::fabs(lat) > 1.4) h = e.z / s - n * (1 - kE2); // near the poles
        lat = std::atan2(e.z, p * (1 - kE2 * n / (n + h)));
    }
    g.lat = lat;
    g.height = h;
    return g;
}

} // namespace gnss::config
