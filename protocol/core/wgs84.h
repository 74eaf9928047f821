#pragma once
// WGS-84, in one place: the ellipsoid's constants, degrees and radians, Earth-centred Earth-fixed
// X, Y, Z (metres) to and from latitude, longitude (degrees) and height above the ellipsoid
// (metres), the metres a degree spans at a latitude (for local east/north offsets), and the
// Earth's mean radius for distances on a sphere. Written here rather than pulled in: a few
// formulas, used by the RTCM station messages, the base-station editors, the simulator, the log
// viewer's statistics, the deviation view and the NTRIP nearest-mountpoint search.
#include <optional>

namespace gnss::wgs84 {

inline constexpr double kA = 6378137.0;           // semi-major axis (m)
inline constexpr double kF = 1.0 / 298.257223563; // flattening
inline constexpr double kE2 = kF * (2.0 - kF);    // first eccentricity squared
inline constexpr double kB = kA * (1.0 - kF);     // semi-minor axis (m)
// The IUGG mean radius (m): for great-circle distances where the ellipsoid would add nothing.
inline constexpr double kMeanRadius = 6371008.8;
// π as std::numbers::pi has it (<numbers> is not included: Qt 6.4's moc cannot parse it, and
// this header reaches files moc reads).
inline constexpr double kPi = 3.141592653589793238462643383279502884;
inline constexpr double kDegree = kPi / 180.0;

constexpr double radians(double degrees) {
    return degrees * kDegree;
}
constexpr double degrees(double radians) {
    return radians / kDegree;
}

struct Ecef {
    double x = 0, y = 0, z = 0; // metres
};

struct Geodetic {
    double latDeg = 0; // positive north
    double lonDeg = 0; // positive east, -180..180
    double height = 0; // metres above the ellipsoid
};

Ecef toEcef(const Geodetic &g);
// None for points within 1 m of the Earth's centre (where latitude means nothing) and for
// non-finite input.
std::optional<Geodetic> toGeodetic(const Ecef &p);

// The metres one degree of latitude (north) and of longitude (east) span at a latitude: the
// meridian and the parallel radius of curvature, per degree.
struct MetresPerDegree {
    double north = 0, east = 0;
};
MetresPerDegree metresPerDegree(double latDeg);

} // namespace gnss::wgs84
