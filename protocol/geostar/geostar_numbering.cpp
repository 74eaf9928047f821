#include "geostar/geostar_numbering.h"

namespace gnss::geostar {

SatelliteRef mapSatellite(Constellation system, int id) {
    // v2.x prints Galileo as 101-136 in GP (and so GN-talker) GSV/GSA sentences; the core's
    // extended numbering keeps 301-336 for Galileo and has nothing at 101-136.
    if ((system == Constellation::Gps || system == Constellation::Unknown) && id >= 101 &&
        id <= 136)
        return {Constellation::Galileo, id - 100};
    return mapSatelliteId(system, id);
}

FixType ggaQuality(int quality) {
    switch (quality) {
    case 0: return FixType::None;
    case 1: return FixType::Fix3D;
    case 2: return FixType::Dgnss;
    case 4: return FixType::RtkFixed;
    case 5: return FixType::RtkFloat;
    case 6: return FixType::Estimated;
    case 7: return FixType::Manual; // fixed coordinates / base station configuration
    case 9: return FixType::Fix3D;  // GeoPath (fix note "GeoPath" belongs to the epoch)
    default: return fixTypeFromGgaQuality(quality);
    }
}

FixType modeIndicator(char mode) {
    return mode == 'G' ? FixType::Fix3D : fixTypeFromModeIndicator(mode);
}

std::string_view fixNote(int ggaQuality, char mode) {
    return ggaQuality == 9 || mode == 'G' ? std::string_view("GeoPath") : std::string_view();
}

} // namespace gnss::geostar
