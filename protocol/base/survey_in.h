#pragma once
// SurveyIn: the workbench's own survey-in. It averages a receiver's positions for a chosen time,
// or until the mean is known to a chosen accuracy, and keeps how the mean converged for a plot.
//
// The mean and the spread are taken in ECEF (Welford's running sums, so hours of 10 Hz fixes
// lose nothing), the spread turned into east, north and up at the mean. The mean's accuracy is
// the 3D spread over √n: honest for independent fixes, optimistic for a receiver whose errors
// wander slowly, so a goal by time is the default and the σ of each axis is always shown.
#include "core/wgs84.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace gnss::base {

struct SurveyGoal {
    std::optional<double> seconds;     // stop after this long (from the first position)
    std::optional<double> accuracy;    // or once the mean's accuracy is this good, metres
    std::size_t minimumPositions = 10; // never before this many
};

struct SurveyStatus {
    std::size_t count = 0;
    double seconds = 0; // from the first position to the last
    wgs84::Geodetic mean;
    wgs84::Ecef meanEcef;
    double sigmaEast = 0, sigmaNorth = 0, sigmaUp = 0; // spread of the positions, metres
    double accuracy = 0;                               // of the mean: 3D spread / √n, metres
};

// One point of the convergence plot: the running mean's offset from the final mean is drawn
// from these (east, north, up of the running mean from the first position) and its accuracy.
struct SurveyPoint {
    double seconds = 0;
    double east = 0, north = 0, up = 0;
    double accuracy = 0;
};

class SurveyIn {
public:
    explicit SurveyIn(const SurveyGoal &goal = {});

    // A position (ellipsoidal height) at `seconds` on the caller's clock.
    void add(double seconds, const wgs84::Geodetic &position);
    SurveyStatus status() const;
    bool done() const;
    // How far along, 0..1: the larger of the time and accuracy goals' shares.
    double progress() const;
    // The convergence, a point per position (at most one per `kPlotStep` seconds kept).
    const std::vector<SurveyPoint> &history() const { return history_; }
    const SurveyGoal &goal() const { return goal_; }
    static constexpr double kPlotStep = 1.0;

private:
    SurveyGoal goal_;
    std::size_t n_ = 0;
    double first_ = 0, last_ = 0;
    wgs84::Ecef origin_; // the first position: sums are taken about it
    double mean_[3] = {0, 0, 0};
    double m2_[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}; // co-moment sums
    std::vector<SurveyPoint> history_;
};

} // namespace gnss::base
