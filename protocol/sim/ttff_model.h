#pragma once
// TtffModel: how long a simulated receiver takes to its first fix after each kind of start, so
// that time-to-first-fix campaigns can be measured against known answers. Per kind a mean and a
// spread (seconds of simulated time); each start draws its own time from a normal distribution
// clamped to [mean / 3, mean × 3] (never instant, a bounded tail).
//
// Families set their own (the VT002 datasheet's averages: hot 12 s, warm 38 s, cold 60 s);
// `gnss-sim --ttff cold=60:8,warm=38:5,hot=12:2,power=3` sets any of them (MEAN[:SPREAD]). The
// power-on start (the program starting the simulator) is 3 s for every family: receivers keep
// their almanac, ephemerides and position in flash, and tests start simulators by the hundred.
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>

namespace gnss::sim {

enum class ResetKind : std::uint8_t {
    PowerCycle, // settings reload from flash, warm start
    Cold,       // command: cold start (almanac/ephemeris dropped), settings kept
    Warm,       // command: warm start, settings kept
    Hot,        // command: hot start, settings kept
};

struct TtffModel {
    struct Dist {
        double mean = -1;  // seconds; < 0: not set (the family's, or the built-in default)
        double spread = 0; // standard deviation, seconds
        bool set() const { return mean >= 0; }
    };
    Dist power, cold, warm, hot;

    // The built-in times: power-on 3 s, hot 2 s, warm 6 s, cold 15 s, no spread (short enough
    // for tests, long enough to see).
    static TtffModel builtin();
    Dist &of(ResetKind k);
    const Dist &of(ResetKind k) const;
    // The kinds set here, over `base`.
    TtffModel over(const TtffModel &base) const;
    // One start's time to first fix (the kind must be set).
    double draw(ResetKind k, std::mt19937 &rng) const;

    // "cold=60:8,warm=38:5,hot=12:2,power=3": the kinds named, MEAN[:SPREAD] seconds. None,
    // with why, when malformed.
    static std::optional<TtffModel> parse(std::string_view spec, std::string &why);
};

} // namespace gnss::sim
