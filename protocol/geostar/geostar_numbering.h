#pragma once
// GeoS-5 satellite numbering and GGA quality (sections 3.1, 3.4, 3.5).
#include "core/fix_type.h"
#include "core/satellite.h"

#include <string_view>

namespace gnss::geostar {

// v2.x under the GP talker: 1-32 GPS, 33-64 SBAS (PRN = id + 87), 65-88 GLONASS (slot = id - 64),
// 101-136 Galileo (id - 100), 193-197 QZSS (PRN = id, J = id - 192).
// v4.10: per talker / GSA system id; Galileo 1-36, QZSS 1-5 (PRN = id + 192, system id 15).
// Only Galileo 101-136 under GP/GN differs from the core's default numbering
// (core/satellite.cpp); everything else is delegated to it.
SatelliteRef mapSatellite(Constellation system, int id);

// GGA quality (table 2): 0 none, 1 autonomous, 2 differential incl. SBAS, 4 fixed RTK,
// 5 float RTK, 6 extrapolated, 7 fixed coordinates (manual / base station), 9 GeoPath
// (GeoS-5MP; a 3D fix, shown with the note "GeoPath").
FixType ggaQuality(int quality);

// Mode letters of GLL/GNS/RMC (table 6): the standard ones plus G, GeoPath (shown as 3D).
FixType modeIndicator(char mode);

// "GeoPath" for GGA quality 9 or mode letter G: shown as 3D with a "GeoPath" note by the badge.
std::string_view fixNote(int ggaQuality, char mode);

} // namespace gnss::geostar
