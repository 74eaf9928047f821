#include "logview/log_view.h"

#include "state/log_scan.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace gnss::logview {

LogView::LogView(const DialectRegistry &registry, LogViewOptions options)
    : registry_(registry), options_(std::move(options)) {}

LogView::~LogView() {
    cancel();
    if (worker_.joinable()) worker_.join();
}

void LogView::open(const std::string &path) {
    cancel();
    if (worker_.joinable()) worker_.join();
    std::lock_guard following(followMutex_);
    std::lock_guard counting(linesMutex_);
    {
        std::unique_lock lock(mutex_);
        lines_ = LineTable();
        map_.close();
        host_ = HostTimes();
        path_ = path;
        error_.clear();
        warnings_.clear();
        gzipped_ = false;
        first_.reset();
        index_ = LogIndex();
        events_.clear();
        timeline_ = TimelineState();
        eventState_ = EventState();
        closedEvents_ = 0;
        goneWarned_ = false;
    }
    cancel_ = false;
    bytesDone_ = bytesTotal_ = 0;
    inflateProgress_ = 0;
    phase_ = static_cast<int>(Phase::Indexing);
    {
        std::lock_guard lock(doneMutex_);
        workerDone_ = false;
    }
    worker_ = std::thread([this, path] { run(path); });
}

void LogView::cancel() {
    cancel_ = true;
}

bool LogView::waitUntilIndexed(int timeoutMs) const {
    std::unique_lock lock(doneMutex_);
    if (timeoutMs < 0) {
        doneCv_.wait(lock, [this] { return workerDone_; });
        return true;
    }
    return doneCv_.wait_for(lock, std::chrono::milliseconds(timeoutMs),
                            [this] { return workerDone_; });
}

void LogView::warn(std::string text) {
    warnings_.push_back(std::move(text));
}

// Whether any sentence of a log without epochs decodes (then it is NMEA, just not positions).
std::string LogView::undecodedReason(std::string_view data, const std::string &path) const {
    const LogScanResult r = scanLog(data, registry_, options_.index.decoder, 1);
    std::uint64_t sentences = 0, missing = 0, bad = 0;
    for (const AddressStats &a : r.addresses) {
        if (a.decoded) return {};
        sentences += a.sentences;
        missing += a.checksumMissing;
        bad += a.checksumBad;
    }
    if (sentences > 0 && missing + bad == sentences) {
        // Sentences there are, refused for their checksums: said, with the way to read them.
        std::string how =
                missing == sentences
                        ? "none of its " + std::to_string(sentences) + " sentences has a checksum"
                : bad == sentences
                        ? "every one of its " + std::to_string(sentences) +
                                  " sentences has a wrong checksum"
                        : "its " + std::to_string(sentences) + " sentences have no checksum (" +
                                  std::to_string(missing) + ") or a wrong one (" +
                                  std::to_string(bad) + ")";
        return "no sentence of " + path + " can be trusted: " + how +
               " (--lenient decodes them anyway)";
    }
    return "no NMEA found in " + path + " (" + std::to_string(data.size()) + " bytes)";
}

// A .gz log: inflated into an unnamed temporary file by a second thread while this one maps the
// file and indexes it as it fills (the first chunk in parallel pieces, then a chunk at a time as
// a followed file is), so that the first epoch is known after the first megabyte, and the index
// is ready soon after the last byte is inflated. False when cancelled or failed (`failure`).
bool LogView::indexWhileInflating(const std::string &path, LogIndex &built, std::uint64_t &start,
                                  bool &cut, std::string &failure) {
    constexpr std::uint64_t kChunk = 8 << 20; // indexed at a time while inflating
    phase_ = static_cast<int>(Phase::Inflating);
    const int fd = createTemporaryFile(failure);
    if (fd < 0) return false;
    const int writer = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    if (writer < 0) {
        failure = "cannot create a temporary file: " + std::string(std::strerror(errno));
        ::close(fd);
        return false;
    }
    {
        std::unique_lock lock(mutex_);
        gzipped_ = true;
        if (!map_.adopt(fd, path)) {
            failure = map_.error();
            ::close(writer);
            return false;
        }
    }
    std::mutex m;
    std::condition_variable cv;
    std::uint64_t inflated = 0;
    bool inflateDone = false, inflateOk = false;
    std::string inflateError;
    std::thread inflater([&] {
        const bool ok = inflateInto(path, writer, inflateError, &cancel_, &inflateProgress_,
                                    [&](std::uint64_t n) {
                                        {
                                            std::lock_guard l(m);
                                            inflated = n;
                                        }
                                        cv.notify_one();
                                    });
        ::close(writer);
        {
            std::lock_guard l(m);
            inflateOk = ok;
            inflateDone = true;
        }
        cv.notify_one();
    });
    IndexControl control;
    control.cancel = &cancel_;
    control.keepOnCancel = true;
    control.onFirstEpoch = [this](const EpochRecord &r) { noteFirstEpoch(r); };
    bool started = false, cancelled = false;
    while (true) {
        bool last = false;
        {
            std::unique_lock l(m);
            const std::uint64_t want =
                    started ? built.indexedEnd + kChunk : options_.startOffset + 1;
            cv.wait(l, [&] { return inflateDone || inflated >= want; });
            last = inflateDone;
        }
        if (cancel_) {
            cancelled = true;
            break;
        }
        std::uint64_t size = 0;
        {
            std::unique_lock lock(mutex_);
            map_.refresh();
            size = map_.size();
        }
        if (last) phase_ = static_cast<int>(Phase::Indexing); // what is left to index
        if (!started) {
            start = std::min(options_.startOffset, size);
            bytesTotal_ = size - start;
            const Checkpoint from = startOfLog(registry_, options_.index.decoder, start);
            if (!buildIndex(map_.base(), map_.bytes(start, size - start), from, registry_,
                            options_.index, built, control)) {
                cancelled = true;
                break;
            }
            started = true;
            if (cancel_) { // what was indexed of the first chunk is kept
                cancelled = true;
                break;
            }
        } else if (size > built.indexedEnd) {
            bytesTotal_ = size - start;
            extendIndex(map_.base(), map_.bytes(built.indexedEnd, size - built.indexedEnd),
                        registry_, options_.index, built);
        }
        // An epoch closed in a later chunk can be the first (a chunk without a whole one).
        if (built.records.size() > built.openRecords) noteFirstEpoch(built.records.front());
        bytesDone_ = built.indexedEnd - start;
        if (last) break;
    }
    inflater.join();
    cut = cancelled;
    if (cancelled) return started; // what was indexed before is an index of a shorter log
    if (!inflateOk) {
        failure = inflateError.empty() ? path + ": cannot inflate" : inflateError;
        return false;
    }
    if (!inflateError.empty()) {
        std::unique_lock lock(mutex_);
        warn(inflateError);
    }
    return true;
}

// Sets the first epoch once, and tells the test hook.
void LogView::noteFirstEpoch(const EpochRecord &r) {
    {
        std::unique_lock lock(mutex_);
        if (first_) return;
        first_ = r;
    }
    if (options_.onFirstEpoch) options_.onFirstEpoch();
}

void LogView::run(std::string path) {
    auto finish = [this](Phase p) {
        phase_ = static_cast<int>(p);
        {
            std::lock_guard lock(doneMutex_);
            workerDone_ = true;
        }
        doneCv_.notify_all();
    };
    auto fail = [&](std::string why) {
        {
            std::unique_lock lock(mutex_);
            error_ = std::move(why);
        }
        finish(Phase::Failed);
    };
    // The map and the host times are set up before anyone else can see them (Indexing phase:
    // readers see an empty index and touch neither).
    MappedLog probe;
    if (!probe.open(path)) return fail(probe.error());
    const bool gz = looksGzipped(probe.bytes(0, 2));
    probe.close();
    LogIndex built;
    std::uint64_t start = 0;
    bool cut = false; // cancelled: the index ends short of the file
    if (gz) {
        std::string failure;
        if (!indexWhileInflating(path, built, start, cut, failure)) {
            if (failure.empty()) return finish(Phase::Cancelled);
            return fail(failure);
        }
    } else {
        {
            std::unique_lock lock(mutex_);
            map_.open(path);
            if (!map_.isOpen()) {
                const std::string e = map_.error();
                lock.unlock();
                return fail(e);
            }
        }
        const std::uint64_t size = map_.size();
        start = std::min(options_.startOffset, size);
        if (options_.hostTimes) {
            std::unique_lock lock(mutex_);
            if (!host_.load(path + ".idx", size) && !host_.error().empty()) warn(host_.error());
        }
        bytesTotal_ = size - start;
        IndexControl control;
        control.cancel = &cancel_;
        control.bytesDone = &bytesDone_;
        control.keepOnCancel = true;
        control.onFirstEpoch = [this](const EpochRecord &r) { noteFirstEpoch(r); };
        const std::string_view data = map_.bytes(start, size - start);
        const Checkpoint from = startOfLog(registry_, options_.index.decoder, start);
        if (!buildIndex(map_.base(), data, from, registry_, options_.index, built, control))
            return finish(Phase::Cancelled);
        cut = built.openEnd < size;
    }
    const std::uint64_t size = map_.size();
    const std::string_view data = map_.bytes(start, size - start);
    {
        std::unique_lock lock(mutex_);
        index_ = std::move(built);
        if (cut) {
            warn("indexing cancelled after " + std::to_string(index_.openEnd - start) +
                 " bytes: the " + std::to_string(index_.records.size()) +
                 " epochs before are kept");
        } else if (index_.records.empty()) {
            if (size == 0)
                warn(path + " is empty");
            else if (index_.framer.sentences == 0)
                warn("no NMEA found in " + path + " (" + std::to_string(size) + " bytes)");
            else if (const std::string why = undecodedReason(data, path); !why.empty())
                warn(why);
            else
                warn("no navigation epoch in " + path + " (" +
                     std::to_string(index_.framer.sentences) + " sentences)");
        }
        if (!index_.records.empty() && !first_) first_ = index_.records.front();
        finishTimeline(0);
        if (map_.liveSize() < size)
            warn(path + " got shorter while it was read: what was read is kept");
    }
    finish(cut ? Phase::Cancelled : Phase::Ready);
}

// Timeline flags and events of records[changedFrom, ...), those of the unfinished last line on
// copies of the state (they are redone when the file grows). Called with the lock held.
void LogView::finishTimeline(std::size_t changedFrom) {
    auto &recs = index_.records;
    const std::size_t closed = recs.size() - std::min(index_.openRecords, recs.size());
    events_.resize(std::min(events_.size(), closedEvents_));
    const HostTimes *host = host_.empty() ? nullptr : &host_;
    if (changedFrom < closed) {
        applyTimeline(recs, changedFrom, closed, timeline_, host, options_.gapFactor);
        collectEvents(recs, changedFrom, closed, registry_, host, eventState_, events_);
    }
    closedEvents_ = events_.size();
    if (closed < recs.size()) {
        TimelineState t = timeline_;
        EventState e = eventState_;
        applyTimeline(recs, closed, recs.size(), t, host, options_.gapFactor);
        collectEvents(recs, closed, recs.size(), registry_, host, e, events_);
    }
}

LogView::Progress LogView::progress() const {
    Progress p;
    p.phase = static_cast<Phase>(phase_.load());
    p.bytesTotal = bytesTotal_.load();
    p.bytesDone = std::min(bytesDone_.load(), p.bytesTotal);
    if (p.phase == Phase::Inflating)
        p.fraction = inflateProgress_.load();
    else if (p.phase == Phase::Ready)
        p.fraction = 1;
    else
        p.fraction = p.bytesTotal ? static_cast<double>(p.bytesDone) / p.bytesTotal : 0;
    return p;
}

std::string LogView::error() const {
    std::shared_lock lock(mutex_);
    return error_;
}

std::vector<std::string> LogView::warnings() const {
    std::shared_lock lock(mutex_);
    return warnings_;
}

std::optional<EpochRecord> LogView::firstEpoch() const {
    std::shared_lock lock(mutex_);
    return first_;
}

std::string LogView::path() const {
    std::shared_lock lock(mutex_);
    return path_;
}

bool LogView::gzipped() const {
    std::shared_lock lock(mutex_);
    return gzipped_;
}

bool LogView::hasHostTimes() const {
    std::shared_lock lock(mutex_);
    return !host_.empty();
}

std::uint64_t LogView::fileSize() const {
    std::shared_lock lock(mutex_);
    return map_.size();
}

std::uint64_t LogView::indexedEnd() const {
    std::shared_lock lock(mutex_);
    return index_.openEnd;
}

FramerStats LogView::framerStats() const {
    std::shared_lock lock(mutex_);
    FramerStats f = index_.framer;
    addFramerStats(f, index_.openFramer);
    return f;
}

std::string LogView::dialectName() const {
    std::shared_lock lock(mutex_);
    return index_.tail.dialect ? std::string(index_.tail.dialect->id) : std::string();
}

std::size_t LogView::epochCount() const {
    std::shared_lock lock(mutex_);
    return index_.records.size();
}

std::optional<EpochRecord> LogView::epoch(std::size_t k) const {
    std::shared_lock lock(mutex_);
    if (k >= index_.records.size()) return std::nullopt;
    return index_.records[k];
}

void LogView::withRecords(const std::function<void(std::span<const EpochRecord>)> &f) const {
    std::shared_lock lock(mutex_);
    f(index_.records);
}

std::uint64_t LogView::epochEnd(std::size_t k) const {
    std::shared_lock lock(mutex_);
    if (k + 1 < index_.records.size()) return index_.records[k + 1].offset;
    return index_.openEnd;
}

bool LogView::lastEpochOpen() const {
    std::shared_lock lock(mutex_);
    return index_.lastIsOpen;
}

std::uint64_t LogView::liveEnd() const {
    return map_.liveSize();
}

bool LogView::stateAt(std::size_t k, ReceiverState &out) const {
    std::shared_lock lock(mutex_);
    if (!map_.isOpen()) return false;
    return stateAtEpoch(map_.base(), liveEnd(), index_, k, registry_, options_.index.decoder, out);
}

std::optional<std::size_t> LogView::epochAt(const TimeSpec &t) const {
    std::shared_lock lock(mutex_);
    const auto &recs = index_.records;
    if (t.kind == TimeSpec::Kind::Epoch)
        return t.epoch < recs.size() ? std::optional<std::size_t>(t.epoch) : std::nullopt;
    // In this order: the first epoch within the typed second [t, t + 1 s); where the log's time
    // crosses t (an epoch at or after t, the timed epoch before it earlier: in a log whose time
    // went back, a receiver reset, that is the epoch of t, not the first epoch later than t);
    // the first epoch at or after t. A log whose time only runs forward gives the first epoch at
    // or after t each way.
    std::optional<std::size_t> crossing, firstAtOrAfter;
    bool earlierBefore = false;
    for (std::size_t i = 0; i < recs.size(); ++i) {
        const EpochRecord &r = recs[i];
        if (!r.hasTime()) continue;
        if (t.kind == TimeSpec::Kind::Utc && !r.has(kDateKnown)) continue;
        const std::int64_t ms = t.kind == TimeSpec::Kind::Utc ? r.utcMs : r.utcMs % 86'400'000;
        if (ms >= t.ms) {
            if (ms < t.ms + 1000) return i;
            if (earlierBefore && !crossing) crossing = i;
            if (!firstAtOrAfter) firstAtOrAfter = i;
        }
        earlierBefore = ms < t.ms;
    }
    return crossing ? crossing : firstAtOrAfter;
}

std::optional<std::size_t> LogView::epochAtOffset(std::uint64_t offset) const {
    std::shared_lock lock(mutex_);
    const auto &recs = index_.records;
    auto it = std::upper_bound(recs.begin(), recs.end(), offset,
                               [](std::uint64_t o, const EpochRecord &r) { return o < r.offset; });
    if (it == recs.begin()) return recs.empty() ? std::nullopt : std::optional<std::size_t>(0);
    return static_cast<std::size_t>(std::prev(it) - recs.begin());
}

std::vector<LogEvent> LogView::events() const {
    std::shared_lock lock(mutex_);
    return events_;
}

std::optional<std::size_t> LogView::nextEvent(std::size_t k) const {
    std::shared_lock lock(mutex_);
    auto it = std::upper_bound(events_.begin(), events_.end(), static_cast<std::uint64_t>(k),
                               [](std::uint64_t v, const LogEvent &e) { return v < e.epoch; });
    if (it == events_.end()) return std::nullopt;
    return static_cast<std::size_t>(it->epoch);
}

std::optional<std::size_t> LogView::previousEvent(std::size_t k) const {
    std::shared_lock lock(mutex_);
    auto it = std::lower_bound(events_.begin(), events_.end(), static_cast<std::uint64_t>(k),
                               [](const LogEvent &e, std::uint64_t v) { return e.epoch < v; });
    if (it == events_.begin()) return std::nullopt;
    return static_cast<std::size_t>(std::prev(it)->epoch);
}

std::string_view LogView::liveData() const {
    return map_.isOpen() ? map_.bytes(0, std::min(map_.size(), liveEnd())) : std::string_view{};
}

std::uint64_t LogView::indexLines(const std::atomic<bool> *cancel) {
    std::lock_guard one(linesMutex_);
    LineTable table;
    {
        // The shared lock keeps the mapping while it is read; the count goes on a copy, swapped
        // in below, so readers see the table before or after, never half of it.
        std::shared_lock lock(mutex_);
        table = lines_;
        if (!table.extend(liveData(), cancel)) return lines_.lineCount();
    }
    std::unique_lock lock(mutex_);
    lines_ = std::move(table);
    return lines_.lineCount();
}

std::uint64_t LogView::lineCount() const {
    std::shared_lock lock(mutex_);
    return lines_.lineCount();
}

std::optional<LineRef> LogView::line(std::uint64_t k) const {
    std::shared_lock lock(mutex_);
    const std::string_view data = liveData();
    if (lines_.scanned() > data.size()) return std::nullopt; // truncated since it was counted
    return lines_.line(data, k);
}

std::uint64_t LogView::lineAt(std::uint64_t offset) const {
    std::shared_lock lock(mutex_);
    const std::string_view data = liveData();
    if (lines_.scanned() > data.size()) return 0;
    return lines_.lineAt(data, offset);
}

bool LogView::findLines(const std::function<bool(std::string_view)> &keep, std::size_t limit,
                        LineTable::Matches &m, const std::atomic<bool> *cancel) const {
    std::shared_lock lock(mutex_);
    const std::string_view data = liveData();
    if (lines_.scanned() > data.size()) return false;
    return lines_.findLines(data, keep, limit, m, cancel);
}

std::vector<LogView::LineRef> LogView::linesAround(std::uint64_t offset, std::size_t before,
                                                   std::size_t after) const {
    std::shared_lock lock(mutex_);
    std::vector<LineRef> out;
    const std::uint64_t size = std::min(map_.size(), liveEnd());
    if (!map_.isOpen() || size == 0) return out;
    offset = std::min(offset, size - 1);
    const char *b = map_.base();
    // Start of the line holding `pos`; a "line" of junk without '\n' is cut every 4096 bytes,
    // like the framer's longest line.
    auto lineStart = [&](std::uint64_t pos) {
        const std::uint64_t floor = pos > Framer::kMaxLine ? pos - Framer::kMaxLine : 0;
        while (pos > floor && b[pos - 1] != '\n') --pos;
        return pos;
    };
    const std::uint64_t holding = lineStart(offset);
    std::uint64_t start = holding;
    for (std::size_t i = 0; i < before && start > 0; ++i) start = lineStart(start - 1);
    std::size_t fromHolding = 0;
    const std::string_view data(b, size);
    for (std::uint64_t pos = start; pos < size;) {
        if (pos >= holding && fromHolding++ >= after) break;
        std::uint64_t next = pos;
        out.push_back(LineTable::lineFrom(data, pos, next)); // the console's line rule
        pos = next;
    }
    return out;
}

std::string_view LogView::bytes(std::uint64_t offset, std::uint64_t length) const {
    std::shared_lock lock(mutex_);
    const std::uint64_t live = liveEnd();
    if (offset >= live) return {};
    return map_.bytes(offset, std::min(length, live - offset));
}

RangeStats LogView::stats(std::size_t first, std::size_t last, bool stationary) const {
    std::shared_lock lock(mutex_);
    return rangeStats(index_.records, first, last, stationary);
}

LogView::Slice LogView::slice(std::size_t first, std::size_t last) const {
    std::shared_lock lock(mutex_);
    const auto &recs = index_.records;
    if (recs.empty() || first >= recs.size()) return {};
    last = std::min(last, recs.size() - 1);
    const std::uint64_t from = recs[first].offset;
    const std::uint64_t to =
            std::min(last + 1 < recs.size() ? recs[last + 1].offset : index_.openEnd, liveEnd());
    if (to <= from) return {};
    const Checkpoint *cp = index_.checkpointFor(first);
    return {map_.bytes(from, to - from), cp ? cp->dialect : nullptr};
}

std::vector<AddressStats> LogView::messageStats(std::size_t first, std::size_t last) const {
    const Slice s = slice(first, last);
    if (s.bytes.empty()) return {};
    DecoderOptions o = options_.index.decoder;
    if (s.dialect) o.dialect = std::string(s.dialect->id);
    return scanLog(s.bytes, registry_, o,
                   options_.index.threads ? options_.index.threads
                                          : std::max(1u, std::thread::hardware_concurrency()))
            .addresses;
}

bool LogView::exportRange(ExportFormat format, std::size_t first, std::size_t last,
                          const ExportSink &sink, const std::string &name) const {
    std::shared_lock lock(mutex_);
    const auto &recs = index_.records;
    if (recs.empty() || first >= recs.size()) {
        // An empty range is still a valid (empty) document.
        if (format == ExportFormat::Gpx) return writeGpx({}, 1, 0, name, sink);
        if (format == ExportFormat::Kml) return writeKml({}, 1, 0, name, sink);
        if (format == ExportFormat::Csv) return writeCsv({}, 1, 0, 0, sink);
        return true;
    }
    last = std::min(last, recs.size() - 1);
    switch (format) {
    case ExportFormat::Gpx: return writeGpx(recs, first, last, name, sink);
    case ExportFormat::Kml: return writeKml(recs, first, last, name, sink);
    case ExportFormat::Csv: return writeCsv(recs, first, last, index_.openEnd, sink);
    case ExportFormat::Nmea: {
        const std::uint64_t from = first == 0 ? index_.start : recs[first].offset;
        std::uint64_t to = last + 1 < recs.size() ? recs[last + 1].offset : index_.openEnd;
        to = std::min(to, liveEnd());
        for (std::uint64_t pos = from; pos < to;) {
            const std::uint64_t n = std::min<std::uint64_t>(to - pos, 4 << 20);
            if (!sink(map_.bytes(pos, n))) return false;
            pos += n;
        }
        return true;
    }
    }
    return false;
}

LogView::FollowResult LogView::follow() {
    FollowResult r;
    if (static_cast<Phase>(phase_.load()) != Phase::Ready) return r;
    std::lock_guard following(followMutex_);
    // 1. Under the lock, briefly: how the file changed, and where the index goes on from.
    LogIndex gain; // the records, checkpoints and end state that the new bytes give
    std::size_t kept = 0;
    std::string_view gained;
    const char *base = nullptr;
    {
        std::unique_lock lock(mutex_);
        if (gzipped_ || !map_.isOpen()) return r;
        const std::uint64_t before = map_.size();
        switch (map_.refresh()) {
        case MappedLog::Change::Unchanged: return r;
        case MappedLog::Change::Gone:
            if (!goneWarned_)
                warn(path_ +
                     " was deleted: what was read is kept (the bytes stay readable while open)");
            goneWarned_ = true;
            return r;
        case MappedLog::Change::Shrunk:
            r.truncated = true;
            warn(path_ + " was cut from " + std::to_string(before) + " to " +
                 std::to_string(map_.size()) +
                 " bytes while open: the epochs read are kept, their lines past the cut are gone");
            return r;
        case MappedLog::Change::Grown: break;
        }
        if (map_.size() <= index_.indexedEnd) return r;
        gained = map_.bytes(index_.indexedEnd, map_.size() - index_.indexedEnd);
        base = map_.base();
        gain.start = index_.start;
        gain.tail = index_.tail;
        gain.indexedEnd = index_.indexedEnd;
        // The records of the unfinished last line are decoded again from the tail.
        kept = index_.records.size() - std::min(index_.openRecords, index_.records.size());
    }
    // 2. Without it: decode what the file gained (megabytes, maybe). Only follow() changes the
    // index and the mapping once it is ready, and it is serialised: `base` and `gained` stay.
    if (options_.whileFollowing) options_.whileFollowing();
    extendIndex(base, gained, registry_, options_.index, gain);
    // 3. Under the lock again, briefly: the new records in.
    std::unique_lock lock(mutex_);
    auto &recs = index_.records;
    recs.resize(kept);
    recs.insert(recs.end(), gain.records.begin(), gain.records.end());
    auto &cps = index_.checkpoints;
    cps.resize(cps.size() - std::min(index_.openCheckpoints, cps.size()));
    for (Checkpoint &c : gain.checkpoints)
        if (index_.checkpoints.empty() || index_.checkpoints.back().carry.emitted < c.carry.emitted)
            index_.checkpoints.push_back(std::move(c));
    addFramerStats(index_.framer, gain.framer);
    index_.tail = std::move(gain.tail);
    index_.indexedEnd = gain.indexedEnd;
    index_.openEnd = gain.openEnd;
    index_.openFramer = gain.openFramer;
    index_.openRecords = gain.openRecords;
    index_.openCheckpoints = gain.openCheckpoints;
    index_.lastIsOpen = gain.lastIsOpen;
    r.firstChanged = kept;
    r.grew = true;
    if (!first_ && !index_.records.empty()) first_ = index_.records.front();
    finishTimeline(r.firstChanged);
    return r;
}

} // namespace gnss::logview
