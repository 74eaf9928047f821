#pragma once
// WGS-84 geodetic conversion: Earth-centred Earth-fixed X, Y, Z (metres) and geodetic latitude,
// longitude (radians) and height above the ellipsoid (metres). Used by the BASEXYZ/BASEBLH
// editors and written here rather than pulled in: two formulas (Bowring's closed form, refined
// by iteration to well below a millimetre).
namespace gnss::config {

struct Ecef {
    double x = 0, y = 0, z = 0;
};
struct Geodetic {
    double lat = 0, lon = 0, height = 0; // radians, radians, metres above the ellipsoid
};

inline constexpr double kWgs84A = 6378137.0;
inline constexpr double kWgs84F = 1.0 / 298.257223563;

Ecef toEcef(const Geodetic &g);
Geodetic toGeodetic(const Ecef &e);

double degrees(double radians);
double radians(double degrees);

} // namespace gnss::config
