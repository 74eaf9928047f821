#pragma once
// Observation: what comparing receivers needs of one navigation epoch, small enough to keep an
// hour of several receivers at 10 Hz: its UTC time of day, fix, position, and the C/N0 of each
// satellite and signal it tracks.
#include "core/fix_type.h"
#include "core/satellite.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace gnss {
struct Epoch;
}

namespace gnss::compare {

struct SignalLevel {
    SatelliteRef sat;
    int signalId = 0; // NMEA 4.10+ signal id; 0 when the receiver does not say
    int cn0 = 0;      // dB-Hz
    bool operator==(const SignalLevel &) const = default;
};

struct Observation {
    std::int64_t timeMs = 0; // UTC time of day, milliseconds
    FixType fix = FixType::None;
    std::optional<double> lat, lon; // degrees
    // Metres: above the ellipsoid when the receiver gives its geoid separation, else above sea.
    std::optional<double> height;
    std::vector<SignalLevel> levels; // tracked ones (with a C/N0)

    bool hasPosition() const { return fix != FixType::None && lat && lon; }
    // None for an epoch without a time (it cannot be matched).
    static std::optional<Observation> of(const Epoch &e);
};

} // namespace gnss::compare
