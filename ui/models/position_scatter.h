#pragma once
// PositionScatter: the deviation plot's statistics, plain C++ so they are tested on their own.
// Keeps the last N positions (lat/lon and fix type), converts them to metres east/north of a
// centre (their mean, or a reference the user typed) on the WGS-84 ellipsoid's local tangent
// plane, and computes:
//   CEP50 / CEP95: the 50th / 95th percentile of the horizontal distance from the centre
//                  (nearest rank: the ceil(p*n)-th smallest distance);
//   2DRMS = 2 * sqrt(sx^2 + sy^2), sx and sy the RMS east and north offsets about the centre
//                  (about the mean these are the population standard deviations).
#include "core/fix_type.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace gnss::ui {

class PositionScatter {
public:
    struct Fix {
        double lat = 0, lon = 0; // degrees
        FixType fix = FixType::None;
    };
    struct Point {
        double east = 0, north = 0; // metres from the centre
        FixType fix = FixType::None;
    };
    struct Stats {
        std::size_t count = 0;
        double centreLat = 0, centreLon = 0;    // degrees: the mean or the reference
        double meanEast = 0, meanNorth = 0;     // mean offset from the centre (0 about the mean)
        double sdEast = 0, sdNorth = 0;         // RMS about the centre
        double cep50 = 0, cep95 = 0, drms2 = 0; // metres
        double maxError = 0;                    // largest horizontal distance
    };

    explicit PositionScatter(std::size_t capacity = 3600) : capacity_(capacity) {}

    // Keeps at most `n` positions (the newest).
    void setCapacity(std::size_t n);
    std::size_t capacity() const { return capacity_; }

    void add(double lat, double lon, FixType fix);
    void clear();
    std::size_t size() const { return fixes_.size(); }

    // Centre on a fixed reference instead of the mean; nullopt returns to the mean.
    void setReference(std::optional<double> lat, std::optional<double> lon);
    bool hasReference() const { return refLat_.has_value() && refLon_.has_value(); }

    // Points in metres about the centre, oldest first, and the statistics (cached until the
    // next change).
    const std::vector<Point> &points() const;
    const Stats &stats() const;

    // Metres east/north of (lat0, lon0) for a nearby (lat, lon): the local tangent plane of the
    // WGS-84 ellipsoid (meridian and prime-vertical radii of curvature at lat0).
    static void toEastNorth(double lat0, double lon0, double lat, double lon, double &east,
                            double &north);
    // Nearest-rank percentile (0 < p <= 1) of unsorted values; 0 for none.
    static double percentile(std::vector<double> values, double p);

private:
    void update() const;

    std::deque<Fix> fixes_;
    std::size_t capacity_;
    std::optional<double> refLat_, refLon_;
    mutable bool dirty_ = true;
    mutable std::vector<Point> points_;
    mutable Stats stats_;
};

} // namespace gnss::ui
