#include "logview/range_stats.h"

#include "core/wgs84.h"
#include "logview/log_time.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

namespace gnss::logview {
namespace {

double percentile(std::vector<double> &v, double p) {
    if (v.empty()) return 0;
    const std::size_t k =
            std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

// A value the index keeps as a float (HDOP, altitude), as the decimal it was printed as: 0.6,
// not the float's 0.6000000238418579.
double printed(float f) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, f).ptr;
    double d = f;
    std::from_chars(buf, end, d);
    return d;
}

// `v` to the nearest 1 / perUnit (1e4: a tenth of a millimetre), for the JSON: digits past what a
// receiver prints or the statistic can hold are noise ("cep50_m": 0.15757527423437667).
std::optional<double> roundedTo(std::optional<double> v, double perUnit) {
    if (!v || !std::isfinite(*v)) return v;
    return std::round(*v * perUnit) / perUnit;
}

bool isFix(FixType f) {
    return f == FixType::Fix2D || f == FixType::Fix3D || f == FixType::Dgnss ||
           f == FixType::RtkFloat || f == FixType::RtkFixed;
}

} // namespace

LocalFrame::LocalFrame(double lat0, double lon0) : lat0_(lat0), lon0_(lon0) {
    const wgs84::MetresPerDegree per = wgs84::metresPerDegree(lat0);
    northPerDeg_ = per.north;
    eastPerDeg_ = per.east;
}

std::pair<double, double> LocalFrame::toEastNorth(double lat, double lon) const {
    double dl = lon - lon0_;
    if (dl > 180) dl -= 360;
    if (dl < -180) dl += 360;
    return {dl * eastPerDeg_, (lat - lat0_) * northPerDeg_};
}

Spread horizontalSpread(std::span<const double> lats, std::span<const double> lons) {
    Spread s;
    const std::size_t n = std::min(lats.size(), lons.size());
    if (n == 0) return s;
    // Mean about the first point (no trouble at the antimeridian for a small spread).
    long double dLat = 0, dLon = 0;
    for (std::size_t i = 0; i < n; ++i) {
        dLat += lats[i] - lats[0];
        double dl = lons[i] - lons[0];
        if (dl > 180) dl -= 360;
        if (dl < -180) dl += 360;
        dLon += dl;
    }
    s.meanLat = lats[0] + static_cast<double>(dLat / n);
    s.meanLon = lons[0] + static_cast<double>(dLon / n);
    const LocalFrame frame(s.meanLat, s.meanLon);
    std::vector<double> r(n);
    double sumSq = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [east, north] = frame.toEastNorth(lats[i], lons[i]);
        r[i] = std::hypot(east, north);
        sumSq += east * east + north * north;
    }
    s.drms2 = 2 * std::sqrt(sumSq / static_cast<double>(n));
    s.cep50 = percentile(r, 0.5);
    s.cep95 = percentile(r, 0.95);
    return s;
}

RangeStats rangeStats(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
                      bool stationary) {
    RangeStats s;
    if (records.empty()) return s;
    last = std::min<std::uint64_t>(last, records.size() - 1);
    if (first > last) return s;
    s.first = first;
    s.last = last;
    s.epochs = last - first + 1;
    bool anySpeed = false;
    if (stationary)
        for (std::uint64_t i = first; i <= last && !anySpeed; ++i)
            anySpeed = records[i].hasPosition() && !std::isnan(records[i].speed);
    s.stationaryOnly = stationary && anySpeed;
    std::vector<double> lats, lons;
    double altSum = 0;
    std::uint64_t altCount = 0;
    std::optional<std::int64_t> prevMs;
    float maxHdop = 0;          // the largest as the index keeps it
    std::int64_t elapsedMs = 0; // whole milliseconds: 16381 steps of 0.1 s add up to 1638, exactly
    for (std::uint64_t i = first; i <= last; ++i) {
        const EpochRecord &r = records[i];
        if (r.fix < s.perFix.size()) ++s.perFix[r.fix];
        if (r.hasTime()) {
            if (!s.startMs) {
                s.startMs = r.utcMs;
                s.dated = r.has(kDateKnown);
            }
            if (prevMs) {
                // Times a log's dates make (a year 9999 beside 1980) do not overflow: the step
                // and the elapsed time stop at the limits of the type.
                std::int64_t stepMs = 0;
                if (__builtin_sub_overflow(r.utcMs, *prevMs, &stepMs))
                    stepMs = r.utcMs > *prevMs ? std::numeric_limits<std::int64_t>::max()
                                               : std::numeric_limits<std::int64_t>::min();
                const double step = static_cast<double>(stepMs) / 1000.0;
                if (stepMs > 0 && __builtin_add_overflow(elapsedMs, stepMs, &elapsedMs))
                    elapsedMs = std::numeric_limits<std::int64_t>::max();
                if (i > first && r.has(kGapBefore)) {
                    ++s.gaps;
                    if (step > s.longestGapS) {
                        s.longestGapS = step;
                        s.longestGapEpoch = i;
                    }
                }
            }
            prevMs = r.utcMs;
            s.endMs = r.utcMs;
        }
        if (i > first && r.has(kTimeBack)) ++s.timeJumps;
        s.checksumErrors += r.checksumErrors;
        if (r.has(kJunk)) ++s.epochsWithJunk;
        const double elapsed = static_cast<double>(elapsedMs) / 1000.0;
        if (!s.timeToFirstFixS && isFix(r.fixType())) s.timeToFirstFixS = elapsed;
        if (!s.timeToRtkFixedS && r.fixType() == FixType::RtkFixed) s.timeToRtkFixedS = elapsed;
        if (!std::isnan(r.hdop) && (!s.maxHdop || r.hdop > maxHdop)) {
            maxHdop = r.hdop;
            s.maxHdop = 0; // made the printed decimal once, after the loop
            s.maxHdopEpoch = i;
        }
        if (r.hasPosition() && (!s.stationaryOnly || (!std::isnan(r.speed) && r.speed < 0.5f))) {
            lats.push_back(r.lat);
            lons.push_back(r.lon);
            if (!std::isnan(r.altMsl)) {
                altSum += printed(r.altMsl);
                ++altCount;
            }
        }
    }
    s.durationS = static_cast<double>(elapsedMs) / 1000.0;
    if (s.maxHdop) s.maxHdop = printed(maxHdop);
    s.positions = lats.size();
    if (!lats.empty()) {
        const Spread sp = horizontalSpread(lats, lons);
        s.meanLat = sp.meanLat;
        s.meanLon = sp.meanLon;
        s.cep50 = sp.cep50;
        s.cep95 = sp.cep95;
        s.drms2 = sp.drms2;
    }
    if (altCount) s.meanAlt = altSum / static_cast<double>(altCount);
    return s;
}

void RangeStats::writeJson(JsonWriter &w) const {
    auto time = [&](const std::optional<std::int64_t> &ms) -> std::optional<std::string> {
        if (!ms) return std::nullopt;
        EpochRecord r;
        r.utcMs = *ms;
        if (dated) r.flags = kDateKnown;
        return formatTime(r);
    };
    w.beginObject().field("first_epoch", first).field("last_epoch", last).field("epochs", epochs);
    w.field("start", time(startMs)).field("end", time(endMs)).field("duration_s", durationS);
    w.key("availability").beginObject();
    for (std::size_t f = 0; f < perFix.size(); ++f)
        if (perFix[f])
            w.field(toString(static_cast<FixType>(f)), // per cent, to 1e-4 (16.6667)
                    roundedTo(availability(static_cast<FixType>(f)), 1e4));
    w.endObject();
    w.key("epochs_per_fix").beginObject();
    for (std::size_t f = 0; f < perFix.size(); ++f)
        if (perFix[f]) w.field(toString(static_cast<FixType>(f)), perFix[f]);
    w.endObject();
    w.field("time_to_first_fix_s", timeToFirstFixS).field("time_to_rtk_fixed_s", timeToRtkFixedS);
    w.field("gaps", gaps).field("longest_gap_s", longestGapS);
    if (longestGapS > 0) w.field("longest_gap_epoch", longestGapEpoch);
    w.field("time_jumps", timeJumps).field("checksum_errors", checksumErrors);
    w.field("epochs_with_junk", epochsWithJunk);
    w.key("position").beginObject();
    w.field("count", positions).field("stationary_only", stationaryOnly);
    // Degrees to 1e-9 (0.1 mm on the ground), metres to 0.1 mm.
    w.field("mean_lat", roundedTo(meanLat, 1e9)).field("mean_lon", roundedTo(meanLon, 1e9));
    w.field("mean_alt_msl", roundedTo(meanAlt, 1e4));
    w.field("cep50_m", roundedTo(cep50, 1e4)).field("cep95_m", roundedTo(cep95, 1e4));
    w.field("drms2_m", roundedTo(drms2, 1e4));
    w.endObject();
    w.field("max_hdop", maxHdop);
    if (maxHdop) w.field("max_hdop_epoch", maxHdopEpoch);
    w.endObject();
}

} // namespace gnss::logview
