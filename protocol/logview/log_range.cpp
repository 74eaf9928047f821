#include "logview/log_range.h"

#include "logview/log_view.h"

namespace gnss::logview {

namespace {

constexpr std::int64_t kDayMs = 86'400'000;
constexpr std::int64_t kTypedSecondMs = 1000;

// What a time of kind `kind` is compared with in an epoch: whole UTC (dated epochs only) or the
// time of day.
bool carries(const EpochRecord &r, TimeSpec::Kind kind) {
    return r.hasTime() && (kind != TimeSpec::Kind::Utc || r.has(kDateKnown));
}
std::int64_t timeOf(const EpochRecord &r, TimeSpec::Kind kind) {
    return kind == TimeSpec::Kind::Utc ? r.utcMs : r.utcMs % kDayMs;
}

// The first and the last epoch that carry a time of `kind`.
struct TimedEnds {
    std::optional<std::size_t> first, last;
};
TimedEnds timedEnds(const LogView &log, TimeSpec::Kind kind) {
    TimedEnds e;
    const std::size_t n = log.epochCount();
    for (std::size_t k = 0; k < n && !e.first; ++k)
        if (const auto r = log.epoch(k); r && carries(*r, kind)) e.first = k;
    for (std::size_t k = n; k > 0 && e.first && !e.last; --k)
        if (const auto r = log.epoch(k - 1); r && carries(*r, kind)) e.last = k - 1;
    return e;
}

} // namespace

std::string epochText(const LogView &log, std::size_t k) {
    const auto r = log.epoch(k);
    const std::string time = r ? formatTime(*r) : std::string();
    const std::string number = "#" + std::to_string(k);
    return time.empty() ? number : time + " (" + number + ")";
}

TimeLookup lookUpTime(const LogView &log, const TimeSpec &t) {
    const std::size_t n = log.epochCount();
    if (t.kind == TimeSpec::Kind::Epoch)
        return t.epoch < n ? TimeLookup{TimePlace::Inside, std::size_t(t.epoch)}
                           : TimeLookup{TimePlace::AfterEnd, 0};
    if (n == 0) return {TimePlace::AfterEnd, 0};
    const TimedEnds ends = timedEnds(log, t.kind);
    if (!ends.first) return {TimePlace::Untimed, 0};
    const auto k = log.epochAt(t);
    if (!k) return {TimePlace::AfterEnd, 0};
    if (*k == *ends.first && timeOf(*log.epoch(*k), t.kind) >= t.ms + kTypedSecondMs)
        return {TimePlace::BeforeStart, *k};
    return {TimePlace::Inside, *k};
}

std::string logSpanText(const LogView &log) {
    const std::size_t n = log.epochCount();
    if (n == 0) return "no epochs";
    return epochText(log, 0) + " to " + epochText(log, n - 1);
}

EpochRange resolveRange(const LogView &log, const std::optional<TimeSpec> &from,
                        const std::optional<TimeSpec> &to) {
    using Refusal = EpochRange::Refusal;
    EpochRange r;
    const std::size_t n = log.epochCount();
    if (n == 0) {
        r.first = 1; // empty
        if (from || to) r.refusal = Refusal::NoEpochs;
        return r;
    }
    r.last = n - 1;
    if (from) {
        const TimeLookup at = lookUpTime(log, *from);
        switch (at.place) {
        case TimePlace::Inside: r.first = at.epoch; break;
        case TimePlace::BeforeStart: r.cutStart = true; break;
        case TimePlace::AfterEnd: r.refusal = Refusal::FromAfterEnd; return r;
        case TimePlace::Untimed: r.refusal = Refusal::Untimed; return r;
        }
    }
    if (to) {
        if (to->kind == TimeSpec::Kind::Epoch) {
            if (to->epoch >= n)
                r.cutEnd = true;
            else
                r.last = std::size_t(to->epoch);
        } else {
            const TimedEnds ends = timedEnds(log, to->kind);
            if (!ends.first) {
                r.refusal = Refusal::Untimed;
                return r;
            }
            const std::int64_t firstMs = timeOf(*log.epoch(*ends.first), to->kind);
            const std::int64_t lastMs = timeOf(*log.epoch(*ends.last), to->kind);
            if (firstMs >= to->ms + kTypedSecondMs) {
                r.refusal = Refusal::ToBeforeStart;
                return r;
            }
            // The last epoch at or before `to`: the one before the first epoch after it.
            TimeSpec after = *to;
            after.ms += 1;
            const auto k = log.epochAt(after);
            if (!k) {
                r.cutEnd = to->ms >= lastMs + kTypedSecondMs;
            } else {
                r.last = *k == *ends.first ? *k : *k - 1; // within the first epoch's second
            }
        }
    }
    if (r.first > r.last) r.refusal = Refusal::Empty;
    return r;
}

} // namespace gnss::logview
