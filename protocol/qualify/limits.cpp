#include "qualify/limits.h"

#include "core/json_writer.h"

#include <charconv>
#include <cmath>

namespace gnss::qualify {

namespace {

constexpr std::pair<LimitStat, std::string_view> kStats[] = {
        {LimitStat::Mean, "mean"}, {LimitStat::Median, "median"}, {LimitStat::P90, "p90"},
        {LimitStat::P95, "p95"},   {LimitStat::Max, "max"},
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

} // namespace

std::string_view toString(LimitStat s) {
    for (const auto &[stat, name] : kStats)
        if (stat == s) return name;
    return "mean";
}

std::optional<Limit> Limit::parse(std::string_view text, std::string &why) {
    const std::string whole(text);
    auto fail = [&](const std::string &what) -> std::optional<Limit> {
        why = "'" + whole + "': " + what +
              " (expected START:STATISTIC<=SECONDS, for example "
              "cold:mean<=60)";
        return std::nullopt;
    };
    std::string_view rest = trimmed(text);
    std::size_t op = rest.find("<=");
    std::size_t opLen = 2;
    if (op == std::string_view::npos) {
        op = rest.find("\xe2\x89\xa4"); // ≤
        opLen = 3;
    }
    if (op == std::string_view::npos) return fail("no <=");
    const std::string_view left = trimmed(rest.substr(0, op));
    const std::string_view right = trimmed(rest.substr(op + opLen));
    std::size_t sep = left.find_first_of(": ");
    if (sep == std::string_view::npos) return fail("no statistic");
    const std::string_view start = trimmed(left.substr(0, sep));
    const std::string_view stat = trimmed(left.substr(sep + 1));
    Limit l;
    if (start == "cold")
        l.start = ReceiverAction::ColdStart;
    else if (start == "warm")
        l.start = ReceiverAction::WarmStart;
    else if (start == "hot")
        l.start = ReceiverAction::HotStart;
    else
        return fail("the start is cold, warm or hot");
    bool known = false;
    for (const auto &[s, name] : kStats)
        if (name == stat) {
            l.stat = s;
            known = true;
        }
    if (!known) return fail("the statistic is mean, median, p90, p95 or max");
    std::string_view number = right;
    if (number.ends_with("s")) number = trimmed(number.substr(0, number.size() - 1));
    double v = 0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
    if (ec != std::errc() || end != number.data() + number.size() || !std::isfinite(v) || v <= 0)
        return fail("the seconds are a positive number");
    l.maxSeconds = v;
    return l;
}

std::string Limit::text() const {
    char b[32];
    std::snprintf(b, sizeof b, "%g", maxSeconds);
    return std::string(toString(start)) + ":" + std::string(toString(stat)) + "<=" + b;
}

double statValue(const StartStats &s, LimitStat stat) {
    switch (stat) {
    case LimitStat::Mean: return s.ttff.mean;
    case LimitStat::Median: return s.ttff.median;
    case LimitStat::P90: return s.p90;
    case LimitStat::P95: return s.ttff.p95;
    case LimitStat::Max: return s.ttff.max;
    }
    return s.ttff.mean;
}

std::vector<LimitResult> checkLimits(const std::vector<Limit> &limits,
                                     const std::vector<TtffRun> &runs) {
    const std::vector<StartStats> stats = statsOf(runs);
    std::vector<LimitResult> out;
    for (const Limit &l : limits) {
        LimitResult r{l, std::nullopt, false};
        for (const StartStats &s : stats)
            if (s.start == l.start && s.fixed > 0) r.value = statValue(s, l.stat);
        r.pass = r.value && *r.value <= l.maxSeconds;
        out.push_back(r);
    }
    return out;
}

void writeLimitsJson(JsonWriter &w, const std::vector<LimitResult> &results) {
    w.key("limits").beginArray();
    for (const LimitResult &r : results) {
        w.beginObject().field("limit", r.limit.text());
        w.field("start", toString(r.limit.start)).field("statistic", toString(r.limit.stat));
        w.field("max_s", r.limit.maxSeconds).field("value_s", r.value).field("pass", r.pass);
        w.endObject();
    }
    w.endArray();
}

} // namespace gnss::qualify
