#pragma once
// PNMRX300-304 reports (almanac, ephemeris, ionosphere, UTC, health) of the simulated GPS
// constellation, built from the sky model's orbits with the nemerix field descriptors and
// encoders (protocol/nemerix), so the values decode back to the orbits the sky model flies:
// circular orbits give e = 0, omega = 0, delta-n = 0; sqrt(A), i0, Omega0 (referred to the GPS
// week as IS-GPS-200 20.3.3.4.3 does) and M0 come from each orbit's radius, plane and phase.
#include "sim/sky_model.h"

#include <string>
#include <vector>

namespace gnss::sim::nemerixdata {

// Reference times (GPS time of week, seconds) for data valid at `tow`: the almanac's toa on a
// 4096 s grid, the ephemeris' toe on a 2-hour grid.
double almanacToa(double tow);
double ephemerisToe(double tow);

// $PNMRX300 for one GPS PRN (empty if the sky has no such satellite). `simTime` is the sky
// model's time matching GPS time of week `tow`, `week` the GPS week.
std::string almanac(const SkyModel &sky, int prn, double simTime, double tow, int week);
// The three $PNMRX301 messages (subframes 1, 2, 3) of one GPS PRN.
std::vector<std::string> ephemeris(const SkyModel &sky, int prn, double simTime, double tow,
                                   int week);
std::string ionosphere(int sv);
std::string utc(int sv, int week, int leapSeconds);
// One health code per GPS PRN 1..32 ("00" healthy, "3F" no satellite).
std::string health(const SkyModel &sky);

} // namespace gnss::sim::nemerixdata
