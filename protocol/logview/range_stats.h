#pragma once
// Statistics of a log or of a range of its epochs: how long, how good the fix, how steady the
// position. Computed from the index alone (no decoding).
#include "core/json_writer.h"
#include "logview/epoch_record.h"

#include <array>
#include <optional>
#include <span>
#include <utility>

namespace gnss::logview {

struct RangeStats {
    std::uint64_t first = 0, last = 0; // epochs [first, last]
    std::uint64_t epochs = 0;
    std::optional<std::int64_t> startMs, endMs; // times of the first and last timed epochs
    bool dated = false;                         // ... full UTC times
    double durationS = 0; // receiver time elapsed (steps back, resets, not counted)
    std::array<std::uint64_t, 9> perFix{}; // epochs per FixType
    std::optional<double> timeToFirstFixS; // from the range's first epoch to a 2D-or-better fix
    std::optional<double> timeToRtkFixedS;
    std::uint64_t gaps = 0;
    double longestGapS = 0;
    std::uint64_t longestGapEpoch = 0; // the first epoch after it
    std::uint64_t timeJumps = 0, checksumErrors = 0, epochsWithJunk = 0;
    // Positions about their mean, metres (horizontal): CEP50, CEP95 and 2DRMS.
    std::uint64_t positions = 0;
    bool stationaryOnly = false; // only epochs with speed < 0.5 m/s were used
    std::optional<double> meanLat, meanLon, meanAlt;
    std::optional<double> cep50, cep95, drms2;
    std::optional<double> maxHdop;
    std::uint64_t maxHdopEpoch = 0;

    double availability(FixType f) const {
        return epochs ? 100.0 * static_cast<double>(perFix[static_cast<std::size_t>(f)]) /
                                static_cast<double>(epochs)
                      : 0.0;
    }
    void writeJson(JsonWriter &w) const;
};

// Statistics of records[first, last] (clamped). `stationary`: the position spread of the epochs
// standing still (speed known and under 0.5 m/s) when there are such, else of all of them.
RangeStats rangeStats(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
                      bool stationary = false);

// Horizontal spread of positions about their mean: CEP50, CEP95, 2DRMS in metres (WGS-84 radii
// of curvature at the mean latitude).
struct Spread {
    double meanLat = 0, meanLon = 0, cep50 = 0, cep95 = 0, drms2 = 0;
};
// East and north metres about a point (WGS-84 radii of curvature at its latitude): exact enough
// for the spread and the track of one receiver (kilometres), not for a continent.
class LocalFrame {
public:
    LocalFrame(double lat0, double lon0); // degrees
    std::pair<double, double> toEastNorth(double lat, double lon) const;

private:
    double lat0_, lon0_, eastPerDeg_ = 0, northPerDeg_ = 0;
};

Spread horizontalSpread(std::span<const double> lats, std::span<const double> lons);

} // namespace gnss::logview
