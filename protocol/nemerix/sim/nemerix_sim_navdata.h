#pragma once
// PNMRX300-304 data (almanac, ephemeris, ionosphere, UTC, health) of the simulated GPS
// constellation, as the nemerix decoders' messages, made from the sky model's orbits in
// engineering units (the messages' setValue scales them as IS-GPS-200 does), so that they decode
// back to the orbits the sky model flies: circular orbits give e = 0, omega = 0, delta-n = 0;
// sqrt(A), i0, Omega0 (referred to the GPS week as IS-GPS-200 20.3.3.4.3 does) and M0 come from
// each orbit's radius, plane and phase. The receiver sends them with the nemerix encoders.
#include "nemerix/nemerix_messages.h"
#include "sim/sky_model.h"

#include <optional>
#include <vector>

namespace gnss::sim::nemerixdata {

// Reference times (GPS time of week, seconds) for data valid at `tow`: the almanac's toa on a
// 4096 s grid, the ephemeris' toe on a 2-hour grid.
double almanacToa(double tow);
double ephemerisToe(double tow);

// The almanac of one GPS PRN (nullopt if the sky has no such satellite). `simTime` is the sky
// model's time matching GPS time of week `tow`, `week` the GPS week.
std::optional<nemerix::Almanac> almanac(const SkyModel &sky, int prn, double simTime, double tow,
                                        int week);
// The three ephemeris messages (subframes 1, 2, 3) of one GPS PRN (none if no such satellite).
std::vector<nemerix::EphemerisSubframe> ephemeris(const SkyModel &sky, int prn, double simTime,
                                                  double tow, int week);
nemerix::Ionosphere ionosphere(int sv);
nemerix::UtcParameters utc(int sv, int week, int leapSeconds);
// One health code per GPS PRN 1..32 ("00" healthy, "3F" no satellite).
nemerix::ConstellationHealth health(const SkyModel &sky);

} // namespace gnss::sim::nemerixdata
