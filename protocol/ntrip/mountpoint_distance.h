#pragma once
// How far a mountpoint's base is from the rover, and which one is nearest: great-circle
// distance on a sphere of the Earth's mean radius, wgs84::kMeanRadius (the source table gives
// positions to a hundredth of a degree at best, so an ellipsoid would add nothing).
#include "ntrip/source_table.h"

#include "core/wgs84.h"

#include <optional>

namespace gnss::ntrip {

// The sphere's radius the distances below are on (the one value: wgs84::kMeanRadius).
inline constexpr double kMeanEarthRadius = wgs84::kMeanRadius;

// Metres along the Earth's surface between two points given in degrees (haversine).
double greatCircleMetres(double lat1Deg, double lon1Deg, double lat2Deg, double lon2Deg);

// The entry's position, when it gives one. Exactly 0/0 is taken as "not given": casters
// write that for network and unlocated streams.
std::optional<std::pair<double, double>> entryPosition(const StreamEntry &s);

struct NearestOptions {
    bool rtcm3Only = true;       // only streams whose format is RTCM 3.x
    bool onlyWantingGga = false; // only streams that take the rover's GGA (network/VRS)
};

struct NearestChoice {
    const StreamEntry *entry = nullptr; // none when no stream qualifies
    double distanceMetres = 0;
};

// The qualifying stream nearest to (latDeg, lonDeg); ties go to the one listed first.
NearestChoice nearestMountpoint(const SourceTable &table, double latDeg, double lonDeg,
                                const NearestOptions &options = {});

} // namespace gnss::ntrip
