#include "logview/log_timeline.h"

#include <algorithm>

namespace gnss::logview {

double usualIntervalMs(const std::vector<EpochRecord> &records) {
    std::vector<std::int64_t> steps;
    std::int64_t prev = kNoTime;
    for (const EpochRecord &r : records) {
        if (steps.size() >= 2000) break;
        if (!r.hasTime()) continue;
        // Within a day is enough for the usual step (a midnight or a date appearing is not one).
        const std::int64_t t = r.utcMs % 86'400'000;
        if (prev != kNoTime && t > prev) steps.push_back(t - prev);
        prev = t;
    }
    if (steps.empty()) return 1000;
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    return static_cast<double>(steps[steps.size() / 2]);
}

void applyTimeline(std::vector<EpochRecord> &records, std::size_t from, std::size_t to,
                   TimelineState &st, const HostTimes *host, double gapFactor) {
    if (st.gapThresholdMs <= 0)
        st.gapThresholdMs = std::max(1000.0, gapFactor * usualIntervalMs(records));
    const bool hostTimes = host && !host->empty();
    for (std::size_t i = from; i < to; ++i) {
        EpochRecord &r = records[i];
        std::uint32_t flags = r.flags;
        if (hostTimes) {
            r.hostMs = host->at(r.offset);
            const auto &gaps = host->gaps();
            while (st.nextLinkGap < gaps.size() && gaps[st.nextLinkGap].offset <= r.offset) {
                flags |= kLinkGap;
                ++st.nextLinkGap;
            }
        }
        if (r.hasTime()) {
            if (!(flags & kDateKnown)) {
                // Time of day only: the nearer reading wins. A step back of more than 12 h is
                // the next day; one forward of more than 12 h is a step back past midnight.
                const std::int64_t ms = r.utcMs;
                if (st.haveTime && ms < st.prevMsOfDay - 43'200'000) {
                    st.dayOffsetMs += 86'400'000;
                    flags |= kMidnight;
                } else if (st.haveTime && ms > st.prevMsOfDay + 43'200'000) {
                    st.dayOffsetMs -= 86'400'000;
                }
                st.prevMsOfDay = ms;
                r.utcMs = ms + st.dayOffsetMs;
            }
            // A date appearing (or lost) is no step of time.
            if (st.haveTime && st.prevDated == ((flags & kDateKnown) != 0)) {
                const std::int64_t step = r.utcMs - st.prevTimeMs;
                if (step < 0) flags |= kTimeBack;
                if (static_cast<double>(step) > st.gapThresholdMs) flags |= kGapBefore;
            }
            st.prevTimeMs = r.utcMs;
            st.prevDated = (flags & kDateKnown) != 0;
            st.haveTime = true;
        }
        if (st.havePrev) {
            if (r.fix != st.prevFix) flags |= kFixChange;
            if (r.station >= 0 && r.station != st.prevStation) flags |= kStationChange;
            // Jamming seen, or gone after it was seen (not a first "no jamming").
            if (r.jamming != 0 && r.jamming != st.prevJamming && (st.prevJamming || r.jamming == 2))
                flags |= kJammingChange;
        }
        if (r.dialect != 0 && r.dialect != st.prevDialect) flags |= kDialectChange;
        st.prevFix = r.fix;
        if (r.station >= 0) st.prevStation = r.station;
        if (r.jamming != 0) st.prevJamming = r.jamming;
        if (r.dialect != 0) st.prevDialect = r.dialect;
        st.havePrev = true;
        r.flags = static_cast<std::uint16_t>(flags);
    }
}

} // namespace gnss::logview
