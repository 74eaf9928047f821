#pragma once
// Events of a log, found in its epoch records: what a timeline marks and a user jumps between.
// Vendor matters (time marks, jamming, base station) come through ReceiverState, filled by each
// dialect's updateState: nothing here names a vendor's sentence or field.
#include "logview/epoch_record.h"
#include "logview/host_times.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss {
class DialectRegistry;
}

namespace gnss::logview {

enum class EventKind : std::uint8_t {
    FixChange,      // "RTK fixed → RTK float"
    Gap,            // no epochs for a while
    LinkGap,        // a recording's link lost / back (FILE.idx)
    ChecksumErrors, // a burst of sentences with wrong checksums (consecutive epochs)
    TimeJump,       // time went back: a receiver reset, or a jump
    DialectChange,  // another receiver family's sentences
    TimeMark,       // the receiver's time mark (event input)
    Jamming,        // jamming detected / cleared
    BaseStation,    // the base/DGPS station changed
};
std::string_view toString(EventKind k); // "fix", "gap", "link", "checksum", "time_jump", ...

struct LogEvent {
    std::uint64_t epoch = 0;  // the epoch where it happens (a gap: the first one after it)
    std::uint64_t offset = 0; // its file offset
    std::int64_t utcMs = kNoTime;
    std::int64_t hostMs = kNoTime;
    bool dated = false; // utcMs is a full UTC time (else a time of day, midnights added)
    EventKind kind = EventKind::FixChange;
    std::string text;
};

// Kept between calls so a followed file's events continue (a checksum burst can go on).
struct EventState {
    bool havePrev = false;
    EpochRecord prev;
    std::int64_t prevTimeMs = kNoTime;
    std::size_t burstEvent = static_cast<std::size_t>(-1); // the burst being extended
    std::uint64_t burstErrors = 0, burstEpochs = 0;
    std::size_t nextLinkGap = 0;
};

// Appends the events of records[from, to) to `out`. `registry` names dialects; `host` gives the
// texts of link gaps.
void collectEvents(std::span<const EpochRecord> records, std::size_t from, std::size_t to,
                   const DialectRegistry &registry, const HostTimes *host, EventState &state,
                   std::vector<LogEvent> &out);

// CSV: epoch,time,host_time,kind,text (RFC 4180 quoting), with a header line. A text a
// spreadsheet would read as a formula (=, +, -, @ first) starts with ' instead.
std::string eventsCsv(std::span<const LogEvent> events);

} // namespace gnss::logview
