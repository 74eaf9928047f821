#include "compare/accuracy.h"

#include "core/json_writer.h"
#include "core/wgs84.h"
#include "state/epoch.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace gnss::compare {

namespace {

std::optional<double> number(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

WithinShares sharesOf(const std::vector<double> &distances) {
    WithinShares w;
    w.epochs = distances.size();
    if (distances.empty()) return w;
    for (std::size_t k = 0; k < kWithinMetres.size(); ++k) {
        std::size_t in = 0;
        for (double d : distances) in += d <= kWithinMetres[k];
        w.percent[k] = 100.0 * double(in) / double(distances.size());
    }
    return w;
}

void writeShares(JsonWriter &w, const WithinShares &s) {
    w.beginObject();
    char name[16];
    for (std::size_t k = 0; k < kWithinMetres.size(); ++k) {
        std::snprintf(name, sizeof name, "%g", kWithinMetres[k]);
        w.field(name, s.percent[k]);
    }
    w.endObject();
}

} // namespace

std::optional<ReferencePoint> ReferencePoint::parse(std::string_view text, std::string &why) {
    std::vector<std::string_view> parts;
    for (std::size_t at = 0;;) {
        const std::size_t comma = text.find(',', at);
        parts.push_back(text.substr(at, comma == std::string_view::npos ? comma : comma - at));
        if (comma == std::string_view::npos) break;
        at = comma + 1;
    }
    if (parts.size() < 2 || parts.size() > 3) {
        why = "expected LAT,LON[,HEIGHT] in degrees and ellipsoidal metres, got '" +
              std::string(text) + "'";
        return std::nullopt;
    }
    const auto lat = number(parts[0]), lon = number(parts[1]);
    if (!lat || *lat < -90 || *lat > 90) {
        why = "latitude must be a number of degrees from -90 to 90, got '" + std::string(parts[0]) +
              "'";
        return std::nullopt;
    }
    if (!lon || *lon < -180 || *lon > 180) {
        why = "longitude must be a number of degrees from -180 to 180, got '" +
              std::string(parts[1]) + "'";
        return std::nullopt;
    }
    ReferencePoint p{*lat, *lon, std::nullopt};
    if (parts.size() == 3) {
        p.height = number(parts[2]);
        if (!p.height || std::abs(*p.height) > 100'000) {
            why = "height must be metres above the ellipsoid, got '" + std::string(parts[2]) + "'";
            return std::nullopt;
        }
    }
    return p;
}

Accuracy::Accuracy(const ReferencePoint &point) : point_(point) {
    const wgs84::Ecef e = wgs84::toEcef({point.latDeg, point.lonDeg, point.height.value_or(0)});
    ecef_[0] = e.x;
    ecef_[1] = e.y;
    ecef_[2] = e.z;
}

bool Accuracy::add(const Epoch &e) {
    if (e.fix == FixType::None || !e.lat || !e.lon) return false;
    // The error rotated into east, north, up at the reference: exact at any distance.
    // Without a height on either side both are put on the ellipsoid's height of the reference.
    const std::optional<double> height = e.altEllipsoid();
    const double h = height && point_.height ? *height : point_.height.value_or(0);
    const wgs84::Ecef p = wgs84::toEcef({*e.lat, *e.lon, h});
    const double dx = p.x - ecef_[0], dy = p.y - ecef_[1], dz = p.z - ecef_[2];
    const double lat = wgs84::radians(point_.latDeg), lon = wgs84::radians(point_.lonDeg);
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    Sample s;
    s.east = -so * dx + co * dy;
    s.north = -sl * co * dx - sl * so * dy + cl * dz;
    if (height && point_.height) s.up = cl * co * dx + cl * so * dy + sl * dz;
    s.fix = e.fix;
    samples_.push_back(s);
    return true;
}

AccuracyReport Accuracy::report() const {
    AccuracyReport r;
    r.positions = samples_.size();
    if (samples_.empty()) return r;
    double sumE = 0, sumN = 0, sumU = 0, sumSq = 0;
    std::vector<double> horizontal, vertical;
    std::map<FixType, std::vector<double>> byFix;
    horizontal.reserve(samples_.size());
    for (const Sample &s : samples_) {
        sumE += s.east;
        sumN += s.north;
        const double d = std::hypot(s.east, s.north);
        sumSq += d * d;
        horizontal.push_back(d);
        byFix[s.fix].push_back(d);
        if (s.up) {
            sumU += *s.up;
            vertical.push_back(std::abs(*s.up));
        }
    }
    const double n = double(samples_.size());
    r.biasEast = sumE / n;
    r.biasNorth = sumN / n;
    r.heights = vertical.size();
    if (!vertical.empty()) r.biasUp = sumU / double(vertical.size());
    r.drms2 = 2 * std::sqrt(sumSq / n);
    r.within = sharesOf(horizontal);
    for (const auto &[fix, distances] : byFix) r.withinByFix[fix] = sharesOf(distances);
    std::vector<double> aboutMean;
    aboutMean.reserve(samples_.size());
    for (const Sample &s : samples_)
        aboutMean.push_back(std::hypot(s.east - r.biasEast, s.north - r.biasNorth));
    std::sort(aboutMean.begin(), aboutMean.end());
    r.cep50 = quantile(aboutMean, 0.50);
    r.cep95 = quantile(aboutMean, 0.95);
    r.horizontal = spreadOf(horizontal);
    r.vertical = spreadOf(vertical);
    return r;
}

void AccuracyReport::writeJson(JsonWriter &w, const ReferencePoint &point) const {
    w.beginObject();
    w.key("point").beginObject().field("lat", point.latDeg).field("lon", point.lonDeg);
    if (point.height) w.field("height", *point.height);
    w.endObject();
    w.field("positions", std::uint64_t(positions)).field("heights", std::uint64_t(heights));
    w.key("bias_m").beginObject().field("east", biasEast).field("north", biasNorth);
    if (biasUp) w.field("up", *biasUp);
    w.endObject();
    w.key("horizontal_m").beginObject();
    w.field("mean", horizontal.mean).field("median", horizontal.median);
    w.field("cep50", cep50).field("cep95", cep95).field("drms2", drms2);
    w.field("r95", horizontal.p95).field("max", horizontal.max).endObject();
    if (heights) {
        w.key("vertical_m").beginObject();
        w.field("mean", vertical.mean).field("median", vertical.median);
        w.field("p95", vertical.p95).field("max", vertical.max).endObject();
    }
    w.key("within");
    writeShares(w, within);
    w.key("within_by_fix").beginObject();
    for (const auto &[fix, shares] : withinByFix) {
        w.key(toString(fix));
        writeShares(w, shares);
    }
    w.endObject().endObject();
}

std::vector<double> Accuracy::horizontalErrors() const {
    std::vector<double> out;
    out.reserve(samples_.size());
    for (const Sample &s : samples_) out.push_back(std::hypot(s.east, s.north));
    return out;
}

std::vector<double> Accuracy::verticalErrors() const {
    std::vector<double> out;
    out.reserve(samples_.size());
    for (const Sample &s : samples_) out.push_back(s.up ? std::abs(*s.up) : std::nan(""));
    return out;
}

bool PositionSet::add(const Epoch &e) {
    if (e.fix == FixType::None || !e.lat || !e.lon) return false;
    add(*e.lat, *e.lon, e.altEllipsoid(), e.fix);
    return true;
}

void PositionSet::add(double latDeg, double lonDeg, std::optional<double> height, FixType fix) {
    points_.push_back({latDeg, lonDeg, height, fix});
}

std::optional<ReferencePoint> PositionSet::mean() const {
    if (points_.empty()) return std::nullopt;
    // Averaged in ECEF, then back: right across the antimeridian as anywhere.
    double x = 0, y = 0, z = 0, h = 0;
    bool heights = true;
    for (const Point &p : points_) {
        const wgs84::Ecef e = wgs84::toEcef({p.lat, p.lon, p.height.value_or(0)});
        x += e.x;
        y += e.y;
        z += e.z;
        heights = heights && p.height;
        h += p.height.value_or(0);
    }
    const double n = double(points_.size());
    const auto g = wgs84::toGeodetic({x / n, y / n, z / n});
    if (!g) return std::nullopt;
    ReferencePoint r;
    r.latDeg = g->latDeg;
    r.lonDeg = g->lonDeg;
    if (heights) r.height = h / n;
    return r;
}

Accuracy PositionSet::against(const ReferencePoint &point) const {
    Accuracy a(point);
    for (const Point &p : points_) {
        Epoch e;
        e.fix = p.fix;
        e.lat = p.lat;
        e.lon = p.lon;
        if (p.height) {
            e.altMsl = *p.height;
            e.geoidSep = 0.0;
        }
        a.add(e);
    }
    return a;
}

} // namespace gnss::compare
