#include "qualify/ttff.h"

#include "core/json_writer.h"
#include "core/wgs84.h"
#include "state/epoch.h"

#include <algorithm>
#include <cmath>

namespace gnss::qualify {

std::string_view toString(RunOutcome o) {
    switch (o) {
    case RunOutcome::Fixed: return "fixed";
    case RunOutcome::TimedOut: return "timeout";
    case RunOutcome::Lost: return "lost";
    }
    return "timeout";
}

RunTracker::RunTracker(ReceiverAction start, int index) {
    run_.start = start;
    run_.index = index;
}

void RunTracker::setReference(double latDeg, double lonDeg) {
    reference_ = std::pair(latDeg, lonDeg);
}

void RunTracker::add(const Epoch &e, double seconds) {
    const bool hasFix = e.fix != FixType::None && e.fix != FixType::Estimated && e.lat && e.lon;
    if (!hasFix) lost_ = true;
    // Until the receiver has dropped the fix it had, what it reports is from before the restart
    // (a second or two at most; a receiver that keeps it through a restart gives none).
    if (!lost_ && seconds < 3.0) return;
    if (!hasFix) return;
    auto first = [seconds](std::optional<double> &t) {
        if (!t) t = seconds;
    };
    first(run_.position);
    if (e.fix >= FixType::Fix2D) first(run_.fix2d);
    if (e.fix >= FixType::Fix3D && !run_.fix3d) {
        run_.fix3d = seconds;
        run_.satellitesAtFix = e.satsUsed;
        if (reference_) {
            const auto m = wgs84::metresPerDegree(reference_->first);
            run_.distanceM = std::hypot((*e.lat - reference_->first) * m.north,
                                        (*e.lon - reference_->second) * m.east);
        }
    }
    if (e.fix >= FixType::Dgnss && e.fix <= FixType::RtkFixed) first(run_.dgnss);
    if (e.fix == FixType::RtkFloat || e.fix == FixType::RtkFixed) first(run_.rtkFloat);
    if (e.fix == FixType::RtkFixed) first(run_.rtkFixed);
}

std::vector<StartStats> statsOf(const std::vector<TtffRun> &runs) {
    std::vector<StartStats> out;
    for (ReceiverAction a :
         {ReceiverAction::ColdStart, ReceiverAction::WarmStart, ReceiverAction::HotStart}) {
        StartStats s;
        s.start = a;
        std::vector<double> times;
        for (const TtffRun &r : runs) {
            if (r.start != a) continue;
            ++s.runs;
            if (r.outcome == RunOutcome::Fixed && r.fix3d) {
                ++s.fixed;
                times.push_back(*r.fix3d);
            }
            s.timeouts += r.outcome == RunOutcome::TimedOut;
            s.lost += r.outcome == RunOutcome::Lost;
        }
        if (!s.runs) continue;
        std::sort(times.begin(), times.end());
        s.p90 = compare::quantile(times, 0.90);
        s.ttff = compare::spreadOf(times);
        out.push_back(s);
    }
    return out;
}

void writeCampaignJson(JsonWriter &w, const std::vector<TtffRun> &runs) {
    w.key("starts").beginObject();
    for (const StartStats &s : statsOf(runs)) {
        w.key(toString(s.start)).beginObject();
        w.field("runs", s.runs).field("fixed", s.fixed).field("timeouts", s.timeouts);
        w.field("lost", s.lost);
        w.key("ttff_s").beginObject();
        if (s.fixed) {
            w.field("mean", s.ttff.mean).field("median", s.ttff.median).field("p90", s.p90);
            w.field("p95", s.ttff.p95).field("min", s.ttff.min).field("max", s.ttff.max);
        }
        w.endObject().endObject();
    }
    w.endObject();
    w.key("runs").beginArray();
    for (const TtffRun &r : runs) {
        w.beginObject().field("start", toString(r.start)).field("run", r.index);
        w.field("outcome", toString(r.outcome));
        auto opt = [&w](const char *k, const std::optional<double> &v) {
            if (v) w.field(k, *v);
        };
        opt("position_s", r.position);
        opt("fix_2d_s", r.fix2d);
        opt("ttff_s", r.fix3d);
        opt("dgnss_s", r.dgnss);
        opt("rtk_float_s", r.rtkFloat);
        opt("rtk_fixed_s", r.rtkFixed);
        if (r.satellitesAtFix) w.field("satellites", *r.satellitesAtFix);
        opt("distance_m", r.distanceM);
        w.endObject();
    }
    w.endArray();
}

} // namespace gnss::qualify
