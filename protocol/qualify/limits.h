#pragma once
// Limits a user sets on a campaign's times to first fix ("cold mean ≤ 60 s", as a datasheet
// promises it), and whether the runs met them. Typed as START:STATISTIC<=SECONDS
// ("cold:mean<=60", "hot:p95<=15"); a limit on a kind with no fixed run fails.
#include "qualify/ttff.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::qualify {

enum class LimitStat : std::uint8_t { Mean, Median, P90, P95, Max };
std::string_view toString(LimitStat s); // "mean", "median", "p90", "p95", "max"

struct Limit {
    ReceiverAction start = ReceiverAction::ColdStart;
    LimitStat stat = LimitStat::Mean;
    double maxSeconds = 0;
    // "cold:mean<=60" (also "cold mean <= 60", "≤"); nullopt with `why` in words.
    static std::optional<Limit> parse(std::string_view text, std::string &why);
    std::string text() const; // "cold:mean<=60"
};

struct LimitResult {
    Limit limit;
    std::optional<double> value; // the statistic measured; none: no run of that kind fixed
    bool pass = false;
};
std::vector<LimitResult> checkLimits(const std::vector<Limit> &limits,
                                     const std::vector<TtffRun> &runs);
// The value of `stat` in `s` (its fixed runs' times).
double statValue(const StartStats &s, LimitStat stat);

// "limits": [{"limit", "start", "statistic", "max_s", "value_s", "pass"}, ...] (a member of the
// object `w` is in).
void writeLimitsJson(JsonWriter &w, const std::vector<LimitResult> &results);

} // namespace gnss::qualify
