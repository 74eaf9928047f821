#include "base/survey_in.h"

#include <algorithm>
#include <cmath>

namespace gnss::base {

namespace {

// The east, north and up unit vectors at a point, in ECEF.
struct Enu {
    double e[3], n[3], u[3];
};

Enu enuAt(const wgs84::Geodetic &g) {
    const double lat = wgs84::radians(g.latDeg), lon = wgs84::radians(g.lonDeg);
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    return {{-so, co, 0}, {-sl * co, -sl * so, cl}, {cl * co, cl * so, sl}};
}

double dot(const double (&a)[3], const double (&b)[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// vᵀ C v for the co-moment sums `m2`, over n − 1.
double variance(const double (&m2)[3][3], const double (&v)[3], std::size_t n) {
    if (n < 2) return 0;
    double s = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s += v[i] * m2[i][j] * v[j];
    return std::max(0.0, s / double(n - 1));
}

} // namespace

SurveyIn::SurveyIn(const SurveyGoal &goal) : goal_(goal) {}

void SurveyIn::add(double seconds, const wgs84::Geodetic &position) {
    const wgs84::Ecef p = wgs84::toEcef(position);
    if (n_ == 0) {
        origin_ = p;
        first_ = seconds;
    }
    last_ = seconds;
    const double d[3] = {p.x - origin_.x, p.y - origin_.y, p.z - origin_.z};
    ++n_;
    double delta[3];
    for (int i = 0; i < 3; ++i) {
        delta[i] = d[i] - mean_[i];
        mean_[i] += delta[i] / double(n_);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m2_[i][j] += delta[i] * (d[j] - mean_[j]);
    const double t = seconds - first_;
    if (history_.empty() || t - history_.back().seconds >= kPlotStep) {
        const Enu axes = enuAt(position);
        history_.push_back(
                {t, dot(axes.e, mean_), dot(axes.n, mean_), dot(axes.u, mean_), status().accuracy});
    }
}

SurveyStatus SurveyIn::status() const {
    SurveyStatus s;
    s.count = n_;
    if (n_ == 0) return s;
    s.seconds = last_ - first_;
    s.meanEcef = {origin_.x + mean_[0], origin_.y + mean_[1], origin_.z + mean_[2]};
    s.mean = wgs84::toGeodetic(s.meanEcef).value_or(wgs84::Geodetic{});
    const Enu axes = enuAt(s.mean);
    s.sigmaEast = std::sqrt(variance(m2_, axes.e, n_));
    s.sigmaNorth = std::sqrt(variance(m2_, axes.n, n_));
    s.sigmaUp = std::sqrt(variance(m2_, axes.u, n_));
    const double spread3d = std::sqrt(s.sigmaEast * s.sigmaEast + s.sigmaNorth * s.sigmaNorth +
                                      s.sigmaUp * s.sigmaUp);
    s.accuracy = n_ >= 2 ? spread3d / std::sqrt(double(n_)) : 0;
    return s;
}

bool SurveyIn::done() const {
    if (n_ < std::max<std::size_t>(goal_.minimumPositions, 2)) return false;
    const SurveyStatus s = status();
    if (goal_.seconds && s.seconds >= *goal_.seconds) return true;
    if (goal_.accuracy && s.accuracy <= *goal_.accuracy) return true;
    return false;
}

double SurveyIn::progress() const {
    if (n_ == 0) return 0;
    if (done()) return 1;
    const SurveyStatus s = status();
    double p = 0;
    if (goal_.seconds && *goal_.seconds > 0) p = std::max(p, s.seconds / *goal_.seconds);
    // The accuracy shrinks as 1/√n: the share of the positions needed so far.
    if (goal_.accuracy && *goal_.accuracy > 0 && s.accuracy > 0)
        p = std::max(p, std::pow(*goal_.accuracy / s.accuracy, 2));
    return std::clamp(p, 0.0, 0.99);
}

} // namespace gnss::base
