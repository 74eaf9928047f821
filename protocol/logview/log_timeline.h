#pragma once
// The flags of an epoch that depend on its neighbours (gaps, time going back, midnight without a
// date, fix/station/jamming/dialect changes) and the host times of a recording, applied to the
// records in file order. Incremental: a followed file goes on from the state kept.
#include "logview/epoch_record.h"
#include "logview/host_times.h"

#include <cstdint>
#include <vector>

namespace gnss::logview {

struct TimelineState {
    double gapThresholdMs = 0;    // 0: not chosen yet (set from the usual interval)
    bool havePrev = false;        // a previous epoch
    bool haveTime = false;        // a previous epoch with a time
    bool prevDated = false;       // ... and whether its date was known
    std::int64_t prevTimeMs = 0;  // its time, midnights added
    std::int64_t prevMsOfDay = 0; // its time of day (dateless midnights)
    std::int64_t dayOffsetMs = 0; // midnights passed without a date
    std::uint8_t prevFix = 0, prevDialect = 0, prevJamming = 0;
    std::int32_t prevStation = -1;
    std::size_t nextLinkGap = 0; // host link gaps already placed
};

// The usual time between epochs (median of the first positive steps), ms; 1000 when unknown.
double usualIntervalMs(const std::vector<EpochRecord> &records);

// Applies the timeline to records[from, to). `gapFactor`: a step over gapFactor × the usual
// interval (and over 1 s) is a gap.
void applyTimeline(std::vector<EpochRecord> &records, std::size_t from, std::size_t to,
                   TimelineState &state, const HostTimes *host, double gapFactor = 2.5);

} // namespace gnss::logview
