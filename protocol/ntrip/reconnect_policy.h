#pragma once
// ReconnectPolicy: how long to wait before trying a correction stream again.
//
// 2 s after the first failure, then 4, 8, 16, 32 and 60 s at most, so a caster that is down is
// not hammered; once a connection has delivered data for a whole minute it counts as healthy
// and the next failure starts again from 2 s. Pure logic on times the caller passes in (ms of
// any monotonic clock), so tests drive it with a fake clock.
#include <cstdint>
#include <optional>

namespace gnss::ntrip {

struct ReconnectSettings {
    std::int64_t firstMs = 2000;
    std::int64_t maxMs = 60000;
    std::int64_t healthyAfterMs = 60000; // data for this long resets the wait
};

class ReconnectPolicy {
public:
    explicit ReconnectPolicy(ReconnectSettings settings = {});

    // Data arrived at `nowMs`.
    void dataReceived(std::int64_t nowMs);
    // The stream failed or dropped: the wait before the next attempt (and the wait after that
    // doubles, up to maxMs, unless the next connection turns out healthy).
    std::int64_t nextDelayMs();
    // Back to the first wait (the user started the stream afresh).
    void reset();

    // Failures since the last healthy stream (or reset).
    int failures() const { return failures_; }
    // The wait nextDelayMs() would return now.
    std::int64_t upcomingDelayMs() const { return next_; }
    const ReconnectSettings &settings() const { return settings_; }

private:
    ReconnectSettings settings_;
    std::int64_t next_;
    int failures_ = 0;
    std::optional<std::int64_t> firstData_; // of the current connection
};

} // namespace gnss::ntrip
