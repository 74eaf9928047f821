#pragma once
// Where a typed time lies in a log, and a range of epochs cut to the log. The command line's
// --from/--to, the window's --at and the timeline's Go to box all ask here, so a time or epoch
// outside the log is refused the same way everywhere (docs/cli.md, "Times and ranges").
#include "logview/log_time.h"

#include <cstddef>
#include <optional>
#include <string>

namespace gnss::logview {

class LogView;

enum class TimePlace {
    Inside,      // the log has an epoch at or after the time, and the time is not before its start
    BeforeStart, // earlier than the log's first epoch (by a second or more)
    AfterEnd,    // later than the log's last epoch, or an epoch number past the last
    Untimed,     // a time, but the log's epochs carry none (or no date, for a whole UTC time)
};

struct TimeLookup {
    TimePlace place = TimePlace::AfterEnd;
    std::size_t epoch = 0; // Inside: the first epoch at or after the time
};

// Where `t` lies in `log`. A time within its second of the first epoch is inside ("10:00:00"
// for a log whose first epoch is 10:00:00.4): users type whole seconds.
TimeLookup lookUpTime(const LogView &log, const TimeSpec &t);

// Epoch k in words: "10:00:00.000 (#0)", or "#0" when it carries no time.
std::string epochText(const LogView &log, std::size_t k);

// The log's first and last epoch in words, for a refusal: "10:00:00.000 (#0) to 10:09:59.000
// (#599)"; an epoch without time is its number alone.
std::string logSpanText(const LogView &log);

// The epochs from `from` to `to` (both included), cut to the log.
struct EpochRange {
    enum class Refusal {
        None,
        FromAfterEnd,  // --from after the log's last epoch
        ToBeforeStart, // --to before its first
        Empty,         // --from after --to: no epoch between them
        Untimed,       // a time given, and the log's epochs carry none
        NoEpochs,      // a time given for a log without epochs
    };
    std::size_t first = 0, last = 0;
    bool cutStart = false; // --from was before the log's start: the range starts at #0
    bool cutEnd = false;   // --to was after its end: the range ends at the last epoch
    Refusal refusal = Refusal::None;
    // An empty log with no --from/--to: first > last, no refusal.
    bool empty() const { return first > last; }
};
EpochRange resolveRange(const LogView &log, const std::optional<TimeSpec> &from,
                        const std::optional<TimeSpec> &to);

} // namespace gnss::logview
