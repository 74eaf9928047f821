// Fuzz harness: the offline log viewer's index (protocol/logview) against one front-to-back
// decode of the same bytes (StreamDecoder + StateTracker), as tests/logview/tst_logview_index.cpp
// checks on generated logs:
//   - buildIndex cut into many pieces on several threads gives byte for byte the records, the
//     framer counts and the end state of one piece on one thread, and as many epochs as the
//     front-to-back decode; each record says what the state says (fix, position, time);
//   - checkpoints are at most N epochs apart, and decoding on from one gives the index's records
//     and the front-to-back states; stateAtEpoch (seek) gives the front-to-back state at the
//     epochs tried;
//   - with bit 4 of byte 2: the log indexed as a growing file (buildIndex on a prefix, then
//     extendIndex on cuts anywhere, mid-line too) gives the same records;
//   - with bit 5 of byte 2: LogView opens the log from a file, and again as a file that grows
//     (follow): both give the same records, timeline flags and events (gaps aside when their
//     threshold comes from the usual step: see checkLogView); the NMEA export of every epoch is
//     the file; seeks, statistics, exports, the console's lines and event jumps hold.
//
// Input: byte 0 picks the decoder options (fuzz_nmea.h; bit 5 repeats the payload into a log
// longer than a line may be), byte 1 the layout: threads 1-4 (bits 0-1) and pieces of
// 16 << (bits 2-4) bytes (16 B to 2 KB, so that a short log is cut into many), byte 2 the
// checkpoint spacing N = 1-16 (bits 0-3) and the modes above, byte 3 seeds the growth cuts and
// the epochs sought. The rest is the log, at most 64 KB (longer inputs are cut).
#include "fuzz_files.h"
#include "fuzz_nmea.h"
#include "logview/log_index.h"
#include "logview/log_view.h"
#include "state/log_scan.h"
#include "state/state_tracker.h"

#include <cstring>

using namespace gnss;
using namespace gnss::fuzz;
using namespace gnss::logview;

namespace {

constexpr std::size_t kMaxLog = 64 << 10;

struct FrontToBack {
    std::vector<ReceiverState> states; // at each epoch, as it completes
    FramerStats framer;
};

FrontToBack frontToBack(std::string_view log, const DecoderOptions &o) {
    StreamDecoder dec(registry(), o);
    StateTracker tracker(dec.dialect());
    FrontToBack r;
    auto onEpoch = [&](const ReceiverState &s) { r.states.push_back(s); };
    dec.feed(log, [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        tracker.setDialect(dec.dialect());
        tracker.add(ev.sentence, *ev.message, ev.dialect, onEpoch);
    });
    dec.finish();
    tracker.flush(onEpoch);
    r.framer = dec.framerStats();
    return r;
}

IndexOptions indexOptions(const DecoderOptions &d, unsigned threads, std::size_t pieceBytes,
                          std::size_t every) {
    IndexOptions o;
    o.decoder = d;
    o.threads = threads;
    o.pieceBytes = pieceBytes;
    o.checkpointEvery = every;
    return o;
}

LogIndex indexOf(std::string_view log, const IndexOptions &o) {
    LogIndex idx;
    check(buildIndex(log.data(), log, startOfLog(registry(), o.decoder, 0), registry(), o, idx),
          "buildIndex gave up without being cancelled");
    return idx;
}

GNSS_FUZZ_NO_COVERAGE std::string describe(const FramerStats &f) {
    return std::to_string(f.bytesIn) + "/" + std::to_string(f.bytesSkipped) + "/" +
           std::to_string(f.sentences) + "/" + std::to_string(f.truncated) + "/" +
           std::to_string(f.tooLong) + "/" + std::to_string(f.binaryAborted);
}

GNSS_FUZZ_NO_COVERAGE bool same(const FramerStats &x, const FramerStats &y) {
    return x.bytesIn == y.bytesIn && x.bytesSkipped == y.bytesSkipped &&
           x.sentences == y.sentences && x.truncated == y.truncated && x.tooLong == y.tooLong &&
           x.binaryAborted == y.binaryAborted;
}

FramerStats total(const LogIndex &idx) {
    FramerStats f = idx.framer;
    addFramerStats(f, idx.openFramer);
    return f;
}

GNSS_FUZZ_NO_COVERAGE void checkSameRecords(const std::vector<EpochRecord> &a,
                                            const std::vector<EpochRecord> &b, const char *what) {
    if (a.size() != b.size())
        fail(what, std::to_string(a.size()) + " and " + std::to_string(b.size()) + " records");
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::memcmp(&a[k], &b[k], sizeof(EpochRecord)) != 0)
            fail(what, "record " + std::to_string(k) + ": offsets " + std::to_string(a[k].offset) +
                               " and " + std::to_string(b[k].offset) + ", flags " +
                               std::to_string(a[k].flags) + " and " + std::to_string(b[k].flags) +
                               ", times " + std::to_string(a[k].utcMs) + " and " +
                               std::to_string(b[k].utcMs));
}

// What the index says of a whole log, whatever the layout it was built with.
GNSS_FUZZ_NO_COVERAGE void checkSameIndex(const LogIndex &a, const LogIndex &b, const char *what) {
    checkSameRecords(a.records, b.records, what);
    check(same(a.framer, b.framer), what,
          "framer " + describe(a.framer) + " vs " + describe(b.framer));
    check(same(a.openFramer, b.openFramer), what, "unfinished line's framer counts differ");
    check(a.indexedEnd == b.indexedEnd && a.openEnd == b.openEnd && a.lastIsOpen == b.lastIsOpen &&
                  a.openRecords == b.openRecords,
          what, "indexed ends differ");
    check(a.tail.sameFuture(b.tail), what, "the state at the indexed end differs");
}

// The index against the front-to-back decode: records, checkpoints, seeks.
void checkAgainstTruth(std::string_view log, const LogIndex &idx, const FrontToBack &truth,
                       std::size_t every, const DecoderOptions &o, Rng &rng) {
    const auto &states = truth.states;
    checkEqual<std::size_t>(idx.records.size(), states.size(),
                            "the index has not the front-to-back decode's epoch count");
    check(same(total(idx), truth.framer), "the index's framer counts are not a decoder's",
          describe(total(idx)) + " vs " + describe(truth.framer));
    checkEqual<std::uint64_t>(idx.openEnd, log.size(), "the index does not reach the log's end");
    for (std::size_t k = 0; k < states.size(); ++k) {
        const EpochRecord &r = idx.records[k];
        if (k > 0) check(r.offset > idx.records[k - 1].offset, "epochs not in file order");
        check(r.offset < log.size(), "an epoch starts past the end of the log");
        const Epoch &e = states[k].epoch;
        check(r.fix == static_cast<std::uint8_t>(e.fix), "a record's fix is not the state's");
        check(r.hasPosition() == (e.lat.has_value() && e.lon.has_value()),
              "a record's position is not the state's");
        if (r.hasPosition())
            check(r.lat == *e.lat && r.lon == *e.lon, "a record's position is not the state's");
        check(r.has(kTimeKnown) == e.time.has_value(), "a record's time is not the state's");
    }

    check(!idx.checkpoints.empty() && idx.checkpoints.front().carry.emitted == 0,
          "no checkpoint at the start of the log");
    for (std::size_t i = 1; i < idx.checkpoints.size(); ++i) {
        const Checkpoint &p = idx.checkpoints[i - 1], &c = idx.checkpoints[i];
        check(c.carry.emitted > p.carry.emitted && c.resume >= p.resume,
              "checkpoints not in order");
        check(c.carry.emitted - p.carry.emitted <= every, "checkpoints more than N epochs apart");
    }
    check(idx.records.size() - std::min<std::size_t>(idx.records.size(),
                                                     idx.checkpoints.back().carry.emitted) <=
                  every,
          "the last epochs are more than N past the last checkpoint",
          std::to_string(idx.records.size()) + " epochs, the last checkpoint after " +
                  std::to_string(idx.checkpoints.back().carry.emitted) + ", " +
                  std::to_string(idx.openRecords) +
                  " from the unfinished line, N = " + std::to_string(every));
    // Decoding on from a checkpoint gives the epochs of the index and the front-to-back states,
    // for the next N + 1 epochs (at most 8 checkpoints tried, spread over the log: every one with
    // N = 1 would cost more than the rest). A checkpoint where a piece began is mid-epoch: its
    // tracker's state() is not the last completed epoch's, what it decodes to is.
    const std::size_t step = idx.checkpoints.size() / 8 + 1;
    for (std::size_t i = 0; i < idx.checkpoints.size(); i += step) {
        const Checkpoint &c = idx.checkpoints[i];
        if (c.carry.emitted >= states.size()) continue;
        const std::size_t first = c.carry.emitted;
        const std::size_t upTo = std::min(states.size(), first + every + 1); // epochs [first, upTo)
        std::size_t k = first;
        EpochRunner::Sinks sinks;
        sinks.onEpoch = [&](EpochRecord &&r, const ReceiverState &s) {
            if (k < upTo) {
                check(std::memcmp(&r, &idx.records[k], sizeof r) == 0,
                      "decoding on from a checkpoint gives another record",
                      "epoch " + std::to_string(k));
                check(s == states[k], "decoding on from a checkpoint gives another state",
                      "epoch " + std::to_string(k));
            }
            ++k;
        };
        EpochRunner runner(registry(), o, log.data(), log.size() + 1, std::move(sinks));
        runner.restore(c);
        // Epoch upTo - 1 completes on the first line of epoch upTo: up to that line's end.
        const std::uint64_t end = upTo < states.size() ? idx.records[upTo].offset : log.size();
        std::size_t stop = end;
        if (end < log.size()) {
            const std::size_t eol = log.find_first_of("\r\n", end);
            stop = eol == std::string_view::npos ? log.size() : eol + 1;
            if (stop < log.size() && log[stop - 1] == '\r' && log[stop] == '\n') ++stop;
        }
        check(c.resume <= stop, "a checkpoint resumes past the epochs after it");
        runner.feed(log.substr(c.resume, stop - c.resume));
        if (stop == log.size()) runner.finish();
        check(k >= upTo, "decoding on from a checkpoint misses epochs",
              std::to_string(k) + " of " + std::to_string(upTo));
    }
    // Seek: the first and last epochs and a few chosen by the input.
    if (states.empty()) return;
    std::vector<std::size_t> ks{0, states.size() - 1};
    for (int i = 0; i < 4; ++i) ks.push_back(rng.below(states.size()));
    for (std::size_t k : ks) {
        ReceiverState s;
        check(stateAtEpoch(log.data(), log.size(), idx, k, registry(), o, s),
              "stateAtEpoch found no state", "epoch " + std::to_string(k));
        check(s == states[k], "stateAtEpoch is not the front-to-back state",
              "epoch " + std::to_string(k));
    }
}

// The log as a file that grows: a prefix indexed, then extended at cuts anywhere.
LogIndex grown(std::string_view log, const IndexOptions &o, Rng &rng) {
    LogIndex idx;
    const std::size_t first = rng.below(log.size() + 1);
    check(buildIndex(log.data(), log.substr(0, first), startOfLog(registry(), o.decoder, 0),
                     registry(), o, idx),
          "buildIndex of a prefix gave up without being cancelled");
    const std::size_t largest = 1 + log.size() / 4;
    for (std::size_t end = first; end < log.size();) {
        end = std::min(log.size(), end + 1 + rng.below(largest));
        extendIndex(log.data(), log.substr(idx.indexedEnd, end - idx.indexedEnd), registry(), o,
                    idx);
    }
    return idx;
}

GNSS_FUZZ_NO_COVERAGE bool sameEvents(const std::vector<LogEvent> &a,
                                      const std::vector<LogEvent> &b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].epoch != b[i].epoch || a[i].offset != b[i].offset || a[i].utcMs != b[i].utcMs ||
            a[i].hostMs != b[i].hostMs || a[i].dated != b[i].dated || a[i].kind != b[i].kind ||
            a[i].text != b[i].text)
            return false;
    return true;
}

std::vector<EpochRecord> recordsOf(const LogView &v) {
    std::vector<EpochRecord> out;
    v.withRecords([&](std::span<const EpochRecord> all) { out.assign(all.begin(), all.end()); });
    return out;
}

void openAndWait(LogView &v, const std::string &path) {
    v.open(path);
    v.waitUntilIndexed();
    check(v.progress().phase == LogView::Phase::Ready, "LogView did not get ready",
          v.error() + " (" + path + ")");
}

// LogView over the log as a file: whole, and followed as it grows.
void checkLogView(std::string_view log, const LogIndex &single, const FrontToBack &truth,
                  const IndexOptions &io, Rng &rng) {
    const std::string path = ScratchDir::get().path("log.nmea");
    removeFile(path + ".idx");
    writeFile(path, log);
    LogViewOptions vo;
    vo.index = io;
    // The gap threshold is gapFactor × the usual step of the epochs known when the log is opened
    // (so a log followed from its first epochs may judge gaps otherwise than the whole); with
    // gapFactor 0 it is a fixed second, and a followed log must give exactly the whole's flags.
    const bool fixedGaps = (rng.next() & 1) != 0;
    if (fixedGaps) vo.gapFactor = 0;
    LogView view(registry(), vo);
    openAndWait(view, path);
    const std::vector<EpochRecord> recs = recordsOf(view);
    checkEqual<std::size_t>(recs.size(), single.records.size(),
                            "LogView has not the index's epoch count");
    for (std::size_t k = 0; k < recs.size(); ++k)
        check(recs[k].offset == single.records[k].offset && recs[k].fix == single.records[k].fix &&
                      std::memcmp(&recs[k].lat, &single.records[k].lat, 16) == 0,
              "LogView's records are not the index's", "epoch " + std::to_string(k));
    checkEqual<std::uint64_t>(view.indexedEnd(), log.size(), "LogView did not read to the end");
    check(same(view.framerStats(), truth.framer), "LogView's framer counts are not a decoder's");
    check(view.lastEpochOpen() == single.lastIsOpen, "LogView's last epoch is not the index's");
    const std::vector<LogEvent> events = view.events();
    for (std::size_t i = 0; i < events.size(); ++i) {
        check(events[i].epoch < recs.size(), "an event past the last epoch");
        check(i == 0 || events[i].epoch >= events[i - 1].epoch, "events not in epoch order");
        check(events[i].offset == recs[events[i].epoch].offset, "an event's offset is not its "
                                                                "epoch's");
    }
    checkJson(
            [&] {
                std::string s;
                JsonWriter w(s);
                view.stats(0, recs.empty() ? 0 : recs.size() - 1).writeJson(w);
                return s;
            }(),
            "range statistics are not valid JSON");
    (void)eventsCsv(events);
    if (!recs.empty()) {
        const std::size_t n = recs.size();
        // The NMEA export of every epoch is the whole file, byte for byte.
        std::string nmea;
        check(view.exportRange(ExportFormat::Nmea, 0, n - 1,
                               [&](std::string_view b) {
                                   nmea.append(b);
                                   return true;
                               }),
              "the NMEA export failed");
        check(nmea == log, "the NMEA export of every epoch is not the log");
        const std::size_t a = rng.below(n), b = a + rng.below(n - a);
        for (ExportFormat f :
             {ExportFormat::Gpx, ExportFormat::Kml, ExportFormat::Csv, ExportFormat::Nmea}) {
            std::uint64_t bytes = 0;
            check(view.exportRange(f, a, b,
                                   [&](std::string_view s) {
                                       bytes += s.size();
                                       return true;
                                   }),
                  "an export failed");
        }
        const RangeStats st = view.stats(a, b, (rng.next() & 1) != 0);
        checkEqual<std::uint64_t>(st.epochs, b - a + 1, "range statistics miscount the epochs");
        std::uint64_t perFix = 0;
        for (std::uint64_t c : st.perFix) perFix += c;
        checkEqual<std::uint64_t>(perFix, st.epochs, "epochs per fix do not add up");
        (void)view.messageStats(a, b);
        const std::size_t k = rng.below(n);
        ReceiverState s;
        check(view.stateAt(k, s) && s == truth.states[k],
              "LogView::stateAt is not the front-to-back state", "epoch " + std::to_string(k));
        check(view.epochAtOffset(recs[k].offset) == k, "epochAtOffset does not find the epoch");
        check(view.epochEnd(k) == (k + 1 < n ? recs[k + 1].offset : log.size()),
              "epochEnd is not where the next epoch starts");
        if (const auto next = view.nextEvent(k)) check(*next > k, "nextEvent is not after");
        if (const auto prev = view.previousEvent(k))
            check(*prev < k, "previousEvent is not before");
        if (recs[k].hasTime()) {
            TimeSpec t;
            t.kind = recs[k].has(kDateKnown) ? TimeSpec::Kind::Utc : TimeSpec::Kind::TimeOfDay;
            t.ms = t.kind == TimeSpec::Kind::Utc ? recs[k].utcMs : recs[k].utcMs % 86'400'000;
            const auto at = view.epochAt(t);
            check(at && *at <= k, "epochAt does not find an epoch at its own time");
        }
    }
    // The console: lines around a place, in order, inside the file, none longer than a line may be.
    const std::vector<LogView::LineRef> lines =
            view.linesAround(rng.below(log.size() + 1), rng.below(8), rng.below(8));
    for (std::size_t i = 0; i < lines.size(); ++i) {
        check(lines[i].offset + lines[i].length <= log.size(), "a console line past the end");
        check(lines[i].length <= Framer::kMaxLine, "a console line longer than a line may be");
        check(i == 0 || lines[i].offset > lines[i - 1].offset, "console lines not in order");
        check(view.bytes(lines[i].offset, lines[i].length).size() == lines[i].length,
              "a console line's bytes are missing");
    }

    // The same file written in two goes and followed: the same records (flags, times) and events.
    const std::size_t cut = rng.below(log.size() + 1);
    writeFile(path, log.substr(0, cut));
    LogView followed(registry(), vo);
    openAndWait(followed, path);
    writeFile(path, log.substr(cut), true);
    const LogView::FollowResult fr = followed.follow();
    check(!fr.truncated, "a file that grew was taken as cut");
    std::vector<EpochRecord> got = recordsOf(followed), want = recs;
    std::vector<LogEvent> gotEvents = followed.events(), wantEvents = events;
    if (!fixedGaps) {
        for (auto *v : {&got, &want})
            for (EpochRecord &r : *v) r.flags &= ~kGapBefore;
        for (auto *v : {&gotEvents, &wantEvents})
            std::erase_if(*v, [](const LogEvent &e) { return e.kind == EventKind::Gap; });
    }
    checkSameRecords(got, want, "a followed log's records differ from the whole's");
    check(sameEvents(gotEvents, wantEvents), "a followed log's events differ from the whole's");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t control = in.byte();
    const DecoderOptions options = decoderOptions(control);
    const std::uint8_t layout = in.byte();
    const unsigned threads = 1 + (layout & 3);
    const std::size_t pieceBytes = std::size_t{16} << ((layout >> 2) & 7);
    const std::uint8_t modes = in.byte();
    const std::size_t every = 1 + (modes & 15);
    Rng rng(in.byte());
    std::string storage;
    const std::string_view log = streamOf(control, in.take(kMaxLog), storage).substr(0, kMaxLog);

    const FrontToBack truth = frontToBack(log, options);
    const IndexOptions io = indexOptions(options, threads, pieceBytes, every);
    const LogIndex single = indexOf(log, indexOptions(options, 1, std::size_t{1} << 40, 64));
    const LogIndex pieces = indexOf(log, io);
    checkSameIndex(pieces, single, "pieces and threads changed the index");
    checkAgainstTruth(log, pieces, truth, every, options, rng);

    if (modes & 16) checkSameIndex(grown(log, io, rng), single, "a log indexed as it grew differs");
    if (modes & 32) checkLogView(log, single, truth, io, rng);
    return 0;
}
