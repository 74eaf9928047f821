#pragma once
// LogView: the offline log viewer's engine (no Qt). Opens a log of any NMEA receiver (this
// tool's recordings with their host times, .gz logs too), indexes it on a worker thread and
// answers what a viewer asks.
//
// How a GUI uses it (every call is thread-safe; none blocks on the indexing):
//
//   LogView view(registry);                 // the application's DialectRegistry
//   view.open("drive.nmea");                // returns at once; a worker maps and indexes
//   // on a timer (10 Hz):
//   auto p = view.progress();               // phase, fraction, bytes; view.cancel() stops it
//                                           // (Cancelled: what was indexed from the start is
//                                           // kept, epochCount() of them, maybe none)
//   if (auto e = view.firstEpoch()) ...     // the first epoch, long before the index is done
//   if (p.phase == LogView::Phase::Ready) { // or view.waitUntilIndexed()
//       view.epochCount(); view.epoch(k);   // EpochRecord: time, fix, position, flags
//       view.withRecords([](std::span<const EpochRecord> all) { ... }); // a timeline, no copy
//       ReceiverState s;
//       view.stateAt(k, s);                 // exactly what a front-to-back decode has at k:
//                                           // feed it to the views (≤ N epochs decoded)
//       view.epochAt(*parseTimeSpec("10:42:00"));   // the epoch at a time
//       view.nextEvent(k), view.previousEvent(k);   // jump between events
//       view.events();                      // time, kind, text; eventsCsv() to save them
//       view.linesAround(offset, 50, 50);   // the lines around an offset: offsets, lengths
//       view.indexLines();                  // (from a worker thread) then a console as a
//       view.lineCount(); view.line(k);     // virtual list over the whole file, line k
//       view.lineAt(view.epochEnd(k));      // ... the line where epoch k ends
//       view.findLines(keep, limit, m);     // (worker) the lines whose address `keep` takes
//       view.bytes(line.offset, line.length);        // ... and the bytes, in the mapping
//       view.stats(from, to);               // availability, TTFF, gaps, CEP, max HDOP
//       view.messageStats(from, to);        // sentences per address in a range
//       view.exportRange(ExportFormat::Gpx, from, to, sink);
//   }
//   view.follow();                          // a file still being written: index what it gained
//                                           // (from a worker thread: readers go on meanwhile)
//
// Problems are reported, never thrown: error() (nothing usable) and warnings() (what was kept).
#include "logview/line_table.h"
#include "logview/log_events.h"
#include "logview/log_export.h"
#include "logview/log_index.h"
#include "logview/log_time.h"
#include "logview/log_timeline.h"
#include "logview/mapped_log.h"
#include "logview/range_stats.h"

#include <condition_variable>
#include <mutex>
#include <shared_mutex>
#include <thread>

namespace gnss::logview {

struct LogViewOptions {
    IndexOptions index;
    double gapFactor = 2.5;        // a step over gapFactor × the usual interval (and 1 s) is a gap
    bool hostTimes = true;         // use FILE.idx of a recording when there is one
    std::uint64_t startOffset = 0; // index from this file offset (the tail of a huge log)
    // Called by follow() on its thread while it decodes what the file gained, holding no lock
    // (a test holds it there to see that every reader goes on meanwhile).
    std::function<void()> whileFollowing;
    // Called by the worker once firstEpoch() answers, before it goes on (a test holds it there
    // to see the first epoch of a .gz log while it is still being inflated).
    std::function<void()> onFirstEpoch;
};

class LogView {
public:
    enum class Phase { Idle, Inflating, Indexing, Ready, Failed, Cancelled };
    struct Progress {
        Phase phase = Phase::Idle;
        double fraction = 0; // of the current phase
        std::uint64_t bytesDone = 0, bytesTotal = 0;
    };
    using LineRef = logview::LineRef;
    struct FollowResult {
        bool grew = false;
        bool truncated = false;       // the file got shorter: reported in warnings()
        std::size_t firstChanged = 0; // records from here on are new (or the last one changed)
    };

    explicit LogView(const DialectRegistry &registry, LogViewOptions options = {});
    ~LogView(); // cancels and joins the worker
    LogView(const LogView &) = delete;
    LogView &operator=(const LogView &) = delete;

    // Opens `path` on a worker thread (a log open before is closed).
    void open(const std::string &path);
    void cancel();
    // Waits for the worker (ready, failed or cancelled); false on timeout (ms, < 0: forever).
    bool waitUntilIndexed(int timeoutMs = -1) const;

    Progress progress() const;
    std::string error() const;
    std::vector<std::string> warnings() const;
    std::optional<EpochRecord> firstEpoch() const;

    // The file.
    std::string path() const;
    bool gzipped() const;
    bool hasHostTimes() const;
    std::uint64_t fileSize() const;
    std::uint64_t indexedEnd() const;
    FramerStats framerStats() const;
    std::string dialectName() const; // the decoder's dialect at the end ("" when none)

    // The index (empty until Ready, or Cancelled with the epochs indexed before).
    std::size_t epochCount() const;
    std::optional<EpochRecord> epoch(std::size_t k) const;
    void withRecords(const std::function<void(std::span<const EpochRecord>)> &f) const;
    std::uint64_t epochEnd(std::size_t k) const; // file offset where epoch k ends
    bool lastEpochOpen() const; // the last epoch was completed by the end of the data

    bool stateAt(std::size_t k, ReceiverState &out) const;
    // The epoch at t: the first within t's second, else where the log's time crosses t, else the
    // first at or after t (in a log whose time only runs forward: the first epoch at or after t).
    std::optional<std::size_t> epochAt(const TimeSpec &t) const;
    std::optional<std::size_t> epochAtOffset(std::uint64_t offset) const;

    std::vector<LogEvent> events() const;
    std::optional<std::size_t> nextEvent(std::size_t k) const;     // epoch of the next event > k
    std::optional<std::size_t> previousEvent(std::size_t k) const; // ... of the last one < k

    // Lines of the file around `offset` (the line holding it included in `after`).
    std::vector<LineRef> linesAround(std::uint64_t offset, std::size_t before,
                                     std::size_t after) const;
    // The whole file as lines (LineTable): indexLines() counts the lines of what the file holds
    // now, past those counted before (about 0.3 s a gigabyte, on the caller's thread: a GUI calls
    // it from a worker, readers go on meanwhile; after follow() it counts what was gained). It
    // returns the line count (and stops, keeping the count before, when `cancel` is set).
    std::uint64_t indexLines(const std::atomic<bool> *cancel = nullptr);
    std::uint64_t lineCount() const;
    std::optional<LineRef> line(std::uint64_t k) const;
    std::uint64_t lineAt(std::uint64_t offset) const; // the line holding offset
    // The counted lines whose address `keep` takes, from m.scannedTo on (LineTable::findLines).
    bool findLines(const std::function<bool(std::string_view)> &keep, std::size_t limit,
                   LineTable::Matches &m, const std::atomic<bool> *cancel = nullptr) const;

    // Bytes of the mapping (valid while the log is open; empty past the end).
    std::string_view bytes(std::uint64_t offset, std::uint64_t length) const;

    // Epochs [first, last] as bytes of the mapping (valid while the log is open) and the dialect
    // in force at the first: what a worker decodes again (a range's signal history).
    struct Slice {
        std::string_view bytes;
        const Dialect *dialect = nullptr; // nullptr: recognised as it goes
    };
    Slice slice(std::size_t first, std::size_t last) const;

    RangeStats stats(std::size_t first, std::size_t last, bool stationary = false) const;
    std::vector<AddressStats> messageStats(std::size_t first, std::size_t last) const;
    // Writes epochs [first, last] in `format` (Nmea: their bytes, exactly).
    bool exportRange(ExportFormat format, std::size_t first, std::size_t last,
                     const ExportSink &sink, const std::string &name = {}) const;

    // Re-checks the file: indexes what it gained (on the caller's thread), reports truncation.
    // What the file gained is decoded without the lock the readers take (the new records are
    // swapped in under it at the end, briefly), so a GUI calls it from a worker thread and goes
    // on drawing meanwhile. Calls are serialised; open() waits for one running.
    FollowResult follow();

private:
    void run(std::string path);
    bool indexWhileInflating(const std::string &path, LogIndex &built, std::uint64_t &start,
                             bool &cut, std::string &failure);
    void noteFirstEpoch(const EpochRecord &r);
    void finishTimeline(std::size_t changedFrom);
    void warn(std::string text);
    // Why a log without epochs has none when its sentences do not decode ("no NMEA found",
    // checksums missing or wrong), empty when some do.
    std::string undecodedReason(std::string_view data, const std::string &path) const;
    std::uint64_t liveEnd() const;
    std::string_view liveData() const; // the mapping up to liveEnd()

    const DialectRegistry &registry_;
    LogViewOptions options_;
    std::thread worker_;
    std::atomic<bool> cancel_{false};
    std::atomic<int> phase_{static_cast<int>(Phase::Idle)};
    std::atomic<std::uint64_t> bytesDone_{0}, bytesTotal_{0};
    std::atomic<double> inflateProgress_{0};
    std::mutex followMutex_; // one follow() at a time; open() waits for it
    mutable std::mutex doneMutex_;
    mutable std::condition_variable doneCv_;
    bool workerDone_ = true;

    mutable std::shared_mutex mutex_; // everything below
    MappedLog map_;
    HostTimes host_;
    std::string path_, error_;
    std::vector<std::string> warnings_;
    bool gzipped_ = false;
    std::optional<EpochRecord> first_;
    LogIndex index_;
    std::vector<LogEvent> events_;
    TimelineState timeline_; // after the closed records
    EventState eventState_;  // after the closed records
    std::size_t closedEvents_ = 0;
    bool goneWarned_ = false; // the file's deletion is reported once
    LineTable lines_;
    std::mutex linesMutex_; // one indexLines() at a time
};

} // namespace gnss::logview
