#pragma once
// The GGA sentence an NTRIP client sends up to the caster: network (VRS) mountpoints compute
// corrections for the rover's position, and many casters close a connection that never sends
// one. Built from a position (the receiver's fix, or one typed in) with a correct checksum.
#include <cstdint>
#include <string>

namespace gnss::ntrip {

struct GgaPosition {
    double latDeg = 0;          // positive north
    double lonDeg = 0;          // positive east
    double altitudeMsl = 0;     // metres above the geoid (a typed ellipsoidal height will do)
    double geoidSeparation = 0; // geoid above the ellipsoid, metres
    int quality = 1;            // GGA fix quality: 1 autonomous, 2 differential, 4 fixed, 5 float
    int satellites = 12;
    double hdop = 1.0;
};

// "$GPGGA,hhmmss.ss,ddmm.mmmmm,N,dddmm.mmmmm,E,q,nn,h.h,a.aaa,M,s.sss,M,,*hh" (no CR LF) at
// `utcMsOfDay` (milliseconds since 00:00 UTC, taken modulo a day). A position that is not finite
// gives a GGA without position and quality 0.
std::string buildGga(const GgaPosition &position, std::int64_t utcMsOfDay);

} // namespace gnss::ntrip
