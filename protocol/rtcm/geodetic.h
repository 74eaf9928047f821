#pragma once
// WGS-84 ECEF ↔ geodetic (latitude, longitude, ellipsoidal height). Written here rather than
// borrowed so the RTCM library stays free of dependencies.
#include <optional>

namespace gnss::rtcm {

struct Geodetic {
    double latDeg = 0; // positive north
    double lonDeg = 0; // positive east, −180..180
    double height = 0; // metres above the ellipsoid
};

struct Ecef {
    double x = 0, y = 0, z = 0; // metres
};

inline constexpr double kWgs84A = 6378137.0;
inline constexpr double kWgs84F = 1.0 / 298.257223563;

// None for points within 1 m of the Earth's centre (where latitude means nothing) and for
// non-finite input.
std::optional<Geodetic> ecefToGeodetic(const Ecef &p);
Ecef geodeticToEcef(const Geodetic &g);

} // namespace gnss::rtcm
