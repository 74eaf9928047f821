#pragma once
// Accuracy: a receiver's positions against a known point (a surveyed mark, a site). Each epoch's
// error east, north and up from the point; over a period the bias (the mean position minus the
// point), the horizontal and vertical error (mean, median, 95 %), R95 and 2DRMS about the point,
// CEP50 and CEP95 about the mean position (the spread alone, bias taken out), and the share of
// epochs within 2 cm, 10 cm, 50 cm, 1 m, 2 m and 5 m, overall and per fix type. What qualifying
// a receiver measures (`gnss-cli summary --reference`). Plain C++.
#include "compare/spread.h"
#include "core/fix_type.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss {
struct Epoch;
class JsonWriter;
} // namespace gnss

namespace gnss::compare {

struct ReferencePoint {
    double latDeg = 0, lonDeg = 0;
    std::optional<double> height; // above the ellipsoid, metres; none: horizontal only
    // "LAT,LON[,HEIGHT]": degrees (positive north and east), ellipsoidal metres. None, with why,
    // when malformed or out of range.
    static std::optional<ReferencePoint> parse(std::string_view text, std::string &why);
};

// The distances the shares are given for, in metres.
inline constexpr std::array<double, 6> kWithinMetres{0.02, 0.10, 0.50, 1.0, 2.0, 5.0};

struct WithinShares {
    std::size_t epochs = 0;
    std::array<double, kWithinMetres.size()> percent{}; // of epochs within each distance
};

struct AccuracyReport {
    std::size_t positions = 0; // epochs with a fix and a position
    std::size_t heights = 0;   // ... with a height above the ellipsoid (the reference has one)
    double biasEast = 0, biasNorth = 0;
    std::optional<double> biasUp;
    Spread horizontal;           // distance from the point: mean, median, p95 (R95), min, max
    double drms2 = 0;            // twice the RMS of the horizontal distance from the point
    double cep50 = 0, cep95 = 0; // radii about the mean position holding 50 % and 95 %
    Spread vertical;             // |up error|: mean, median, p95 (vertical 95 %)
    WithinShares within;         // horizontal, every epoch
    std::map<FixType, WithinShares> withinByFix;

    // {"point": {...}, "positions", "bias_m": {east, north, up}, "horizontal_m": {mean, median,
    // cep50, cep95, drms2, r95, max}, "vertical_m": {mean, median, p95, max} (when heights),
    // "within": {"0.02": %, ...}, "within_by_fix": {"3d": {...}, ...}}
    void writeJson(JsonWriter &w, const ReferencePoint &point) const;
};

class Accuracy {
public:
    explicit Accuracy(const ReferencePoint &point);

    // An epoch with a fix and a position counts (true); others are skipped. Its height counts
    // when it is above the ellipsoid (the receiver gives its geoid separation).
    bool add(const Epoch &e);
    AccuracyReport report() const;
    const ReferencePoint &point() const { return point_; }
    // Every position's horizontal distance from the point, metres, in the order added (for a
    // histogram or a plot over time).
    std::vector<double> horizontalErrors() const;
    // ... and each one's vertical distance |up| (NaN where a position or the point has no height).
    std::vector<double> verticalErrors() const;

private:
    struct Sample {
        double east, north;
        std::optional<double> up;
        FixType fix;
    };
    ReferencePoint point_;
    double ecef_[3];
    std::vector<Sample> samples_;
};

// Positions kept to be measured later: against a point given then, or against their own mean
// (the accuracy "of the period" when no reference is known). What the live and the log views use.
class PositionSet {
public:
    // An epoch with a fix and a position is kept (true).
    bool add(const Epoch &e);
    // A position (degrees; height above the ellipsoid when known).
    void add(double latDeg, double lonDeg, std::optional<double> height, FixType fix);
    std::size_t size() const { return points_.size(); }
    void clear() { points_.clear(); }
    // Their mean (with a height when every position has one); nullopt when empty.
    std::optional<ReferencePoint> mean() const;
    // Every position measured against `point`.
    Accuracy against(const ReferencePoint &point) const;

private:
    struct Point {
        double lat, lon;
        std::optional<double> height;
        FixType fix;
    };
    std::vector<Point> points_;
};

} // namespace gnss::compare
