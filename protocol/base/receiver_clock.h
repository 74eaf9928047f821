#pragma once
// ReceiverClock: a receiver's own time as one growing count of seconds, from its epochs' UTC
// time of day (a day added each time it wraps past midnight). A survey of M minutes is M minutes
// of the receiver's positions, whatever the pace they arrive at: a simulator run faster than real
// time, a replay.
#include "core/field_types.h"

#include <optional>

namespace gnss::base {

class ReceiverClock {
public:
    // An epoch's time of day (none: the clock stays where it is).
    void add(const std::optional<TimeOfDay> &time) {
        if (!time) return;
        double t = static_cast<double>(time->nanos) / 1e9 + day_;
        if (timed_ && t < seconds_ - 43200) day_ += 86400, t += 86400;
        seconds_ = t;
        timed_ = true;
    }
    bool timed() const { return timed_; } // an epoch with a time has come
    double seconds() const { return seconds_; }

private:
    double seconds_ = 0, day_ = 0;
    bool timed_ = false;
};

} // namespace gnss::base
