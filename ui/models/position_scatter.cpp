#include "models/position_scatter.h"

#include "core/wgs84.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gnss::ui {

void PositionScatter::setCapacity(std::size_t n) {
    capacity_ = std::max<std::size_t>(1, n);
    while (fixes_.size() > capacity_) fixes_.pop_front();
    dirty_ = true;
}

void PositionScatter::add(double lat, double lon, FixType fix) {
    fixes_.push_back({lat, lon, fix});
    while (fixes_.size() > capacity_) fixes_.pop_front();
    dirty_ = true;
}

void PositionScatter::clear() {
    fixes_.clear();
    dirty_ = true;
}

void PositionScatter::setReference(std::optional<double> lat, std::optional<double> lon) {
    refLat_ = lat;
    refLon_ = lon;
    dirty_ = true;
}

const std::vector<PositionScatter::Point> &PositionScatter::points() const {
    update();
    return points_;
}

const PositionScatter::Stats &PositionScatter::stats() const {
    update();
    return stats_;
}

void PositionScatter::toEastNorth(double lat0, double lon0, double lat, double lon, double &east,
                                  double &north) {
    const wgs84::MetresPerDegree per = wgs84::metresPerDegree(lat0);
    double dLon = lon - lon0;
    if (dLon > 180.0) dLon -= 360.0;
    if (dLon < -180.0) dLon += 360.0;
    east = dLon * per.east;
    north = (lat - lat0) * per.north;
}

double PositionScatter::percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

void PositionScatter::update() const {
    if (!dirty_) return;
    dirty_ = false;
    points_.clear();
    stats_ = Stats{};
    const std::size_t n = fixes_.size();
    stats_.count = n;
    if (n == 0) return;

    double lat0 = 0, lon0 = 0;
    if (hasReference()) {
        lat0 = *refLat_;
        lon0 = *refLon_;
    } else {
        // Longitudes are averaged as offsets from the first so a spread across ±180° stays whole.
        const double first = fixes_.front().lon;
        double dl = 0;
        for (const Fix &f : fixes_) {
            lat0 += f.lat;
            double d = f.lon - first;
            if (d > 180.0) d -= 360.0;
            if (d < -180.0) d += 360.0;
            dl += d;
        }
        lat0 /= static_cast<double>(n);
        lon0 = first + dl / static_cast<double>(n);
    }
    stats_.centreLat = lat0;
    stats_.centreLon = lon0;

    points_.reserve(n);
    std::vector<double> r;
    r.reserve(n);
    double se = 0, sn = 0, se2 = 0, sn2 = 0;
    for (const Fix &f : fixes_) {
        Point p;
        toEastNorth(lat0, lon0, f.lat, f.lon, p.east, p.north);
        p.fix = f.fix;
        points_.push_back(p);
        r.push_back(std::hypot(p.east, p.north));
        se += p.east;
        sn += p.north;
        se2 += p.east * p.east;
        sn2 += p.north * p.north;
    }
    const double dn = static_cast<double>(n);
    stats_.meanEast = se / dn;
    stats_.meanNorth = sn / dn;
    stats_.sdEast = std::sqrt(se2 / dn);
    stats_.sdNorth = std::sqrt(sn2 / dn);
    stats_.drms2 = 2.0 * std::sqrt(stats_.sdEast * stats_.sdEast + stats_.sdNorth * stats_.sdNorth);
    stats_.maxError = *std::max_element(r.begin(), r.end());
    stats_.cep50 = percentile(r, 0.50);
    stats_.cep95 = percentile(std::move(r), 0.95);
}

} // namespace gnss::ui
