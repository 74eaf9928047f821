#include "ntrip/reconnect_policy.h"

#include <algorithm>

namespace gnss::ntrip {

ReconnectPolicy::ReconnectPolicy(ReconnectSettings settings)
    : settings_(settings), next_(std::max<std::int64_t>(settings.firstMs, 0)) {
    settings_.firstMs = next_;
    settings_.maxMs = std::max(settings_.maxMs, settings_.firstMs);
}

void ReconnectPolicy::dataReceived(std::int64_t nowMs) {
    if (!firstData_) firstData_ = nowMs;
    if (nowMs - *firstData_ >= settings_.healthyAfterMs) {
        next_ = settings_.firstMs;
        failures_ = 0;
    }
}

std::int64_t ReconnectPolicy::nextDelayMs() {
    const std::int64_t d = next_;
    // Doubling from 0 would stay 0: a zero first wait (tests) grows from 1 ms.
    next_ = std::min(std::max<std::int64_t>(next_ * 2, 1), settings_.maxMs);
    ++failures_;
    firstData_.reset();
    return d;
}

void ReconnectPolicy::reset() {
    next_ = settings_.firstMs;
    failures_ = 0;
    firstData_.reset();
}

} // namespace gnss::ntrip
