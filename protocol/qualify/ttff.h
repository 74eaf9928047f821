#pragma once
// Time to first fix, measured: one run (a restart and the fixes that follow it, on the host's
// clock from the moment the restart was written), and the statistics of a campaign's runs per
// kind of start, as datasheets state them (the time to 3D). Plain C++: the campaign that drives a
// receiver (ttff_campaign.h), gnss-cli ttff and the Qualification views share it.
#include "compare/spread.h"
#include "core/dialect.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gnss {
struct Epoch;
class JsonWriter;
} // namespace gnss

namespace gnss::qualify {

enum class RunOutcome : std::uint8_t {
    Fixed,    // reached a 3D fix within the timeout
    TimedOut, // did not
    Lost,     // the link went away during the run
};
std::string_view toString(RunOutcome o); // "fixed", "timeout", "lost"

struct TtffRun {
    ReceiverAction start = ReceiverAction::ColdStart;
    int index = 0; // 1.. within its kind
    RunOutcome outcome = RunOutcome::TimedOut;
    // Seconds from the restart written to the first epoch with ...
    std::optional<double> position, fix2d, fix3d, dgnss, rtkFloat, rtkFixed;
    std::optional<int> satellitesAtFix; // used at the first 3D fix
    std::optional<double> distanceM;    // of the first 3D fix from the reference, when one
};

// Follows one run: the epochs after the restart, with their host time since it was written.
// The restart's own effect (the old fix still reported for an epoch or two) is not a first fix:
// only epochs after one without a fix count (`needLoss`), unless the receiver never loses it.
class RunTracker {
public:
    RunTracker(ReceiverAction start, int index);
    // An epoch `seconds` after the restart was written.
    void add(const Epoch &e, double seconds);
    const TtffRun &run() const { return run_; }
    bool fixed3d() const { return run_.fix3d.has_value(); }
    // Where the first fix is measured from (for the distance).
    void setReference(double latDeg, double lonDeg);
    void finish(RunOutcome outcome) { run_.outcome = outcome; }

private:
    TtffRun run_;
    bool lost_ = false; // the fix was seen gone since the restart
    std::optional<std::pair<double, double>> reference_;
};

struct StartStats {
    ReceiverAction start = ReceiverAction::ColdStart;
    int runs = 0, fixed = 0, timeouts = 0, lost = 0;
    compare::Spread ttff; // of the runs that fixed: mean, median, p95, min, max (seconds)
    double p90 = 0;
};
std::vector<StartStats> statsOf(const std::vector<TtffRun> &runs);

// {"starts": {"cold": {"runs", "fixed", "timeouts", "lost", "ttff_s": {mean, median, p90, p95,
// min, max}}, ...}, "runs": [{"start", "run", "outcome", "position_s", "fix_2d_s", "ttff_s",
// "dgnss_s", "rtk_float_s", "rtk_fixed_s", "satellites", "distance_m"}, ...]} (members of the
// object `w` is in: the caller opens and closes it).
void writeCampaignJson(JsonWriter &w, const std::vector<TtffRun> &runs);

} // namespace gnss::qualify
