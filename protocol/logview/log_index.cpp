#include "logview/log_index.h"

#include "state/log_scan.h"

#include <algorithm>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace gnss::logview {
namespace {

struct PieceRun {
    std::vector<EpochRecord> records;
    std::vector<Checkpoint> checkpoints;
    Checkpoint end;
    FramerStats framer;
    bool done = false;
    bool partial = false; // cancelled part way, `end` where it stopped (piece 0, keepOnCancel)
};

Checkpoint freshStart(const DialectRegistry &registry, const DecoderOptions &options,
                      std::uint64_t offset) {
    return startOfLog(registry, options, offset);
}

std::uint64_t offsetOf(const char *base, const char *p) {
    return static_cast<std::uint64_t>(p - base);
}

// Reserves room for `n` records in a vector not yet written, asking for huge pages where the
// system grants them on request: the index of a 1 GB log is 52 MB, and filling it 4 KB page by
// page costs a tenth of a second of page faults on a virtual machine.
void reserveRecords(std::vector<EpochRecord> &v, std::size_t n) {
    v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = 2u << 20;
    const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
    const std::uintptr_t from = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t to = (begin + v.capacity() * sizeof(EpochRecord)) & ~(kHuge - 1);
    if (to > from) ::madvise(reinterpret_cast<void *>(from), to - from, MADV_HUGEPAGE);
#endif
}

// A piece's records, reserved from its size (a dense 10 Hz log has an epoch per kilobyte): no
// copying as the vector grows. Pages not written are never touched.
constexpr std::size_t kBytesPerEpochGuess = 512;

// Appends a checkpoint unless one for the same epoch count is already last.
void addCheckpoint(std::vector<Checkpoint> &cps, Checkpoint &&c) {
    if (!cps.empty() && cps.back().carry.emitted >= c.carry.emitted) return;
    cps.push_back(std::move(c));
}

} // namespace

const Checkpoint *LogIndex::checkpointFor(std::uint64_t k) const {
    auto it = std::upper_bound(
            checkpoints.begin(), checkpoints.end(), k,
            [](std::uint64_t v, const Checkpoint &c) { return v < c.carry.emitted; });
    if (it == checkpoints.begin()) return nullptr;
    return &*std::prev(it);
}

Checkpoint startOfLog(const DialectRegistry &registry, const DecoderOptions &options,
                      std::uint64_t start) {
    Checkpoint c;
    c.resume = start;
    StreamDecoder probe(registry, options);
    c.dialect = probe.dialect();
    c.tracker = StateTracker(c.dialect);
    c.carry.epochStart = start;
    return c;
}

// Completes the index after `out.tail`: the unfinished line (if any) and the epoch in progress,
// as a decoder does at the end of its input, into a copy of the tail state.
void closeIndex(const char *base, std::string_view unfinished, const DialectRegistry &registry,
                const IndexOptions &options, LogIndex &out) {
    EpochRunner::Sinks sinks;
    sinks.onEpoch = [&out](EpochRecord &&r, const ReceiverState &) { out.records.push_back(r); };
    // A line ended by a last CR closes an epoch: the checkpoint after it keeps the last epochs
    // within N of one (dropped with the open records when the file grows).
    const std::size_t checkpointsBefore = out.checkpoints.size();
    sinks.onCheckpoint = [&out](Checkpoint &&c) { addCheckpoint(out.checkpoints, std::move(c)); };
    EpochRunner last(registry, options.decoder, base, options.checkpointEvery, std::move(sinks));
    last.restore(out.tail);
    const std::size_t before = out.records.size();
    last.feed(unfinished);
    last.finish();
    out.openFramer = last.framerStats();
    out.openEnd = out.indexedEnd + unfinished.size();
    out.openCheckpoints = out.checkpoints.size() - checkpointsBefore;
    out.openRecords = out.records.size() - before;
    out.lastIsOpen = out.openRecords > 0;
}

// Splits off what follows the last line end (lastLineEnd: a LF, or a CR not last).
std::pair<std::string_view, std::string_view> atLastLineEnd(std::string_view data) {
    const std::size_t cut = lastLineEnd(data);
    return {data.substr(0, cut), data.substr(cut)};
}

bool buildIndex(const char *base, std::string_view whole, const Checkpoint &from,
                const DialectRegistry &registry, const IndexOptions &options, LogIndex &out,
                const IndexControl &control) {
    const auto [data, unfinished] = atLastLineEnd(whole);
    const unsigned threads =
            options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    const std::size_t every = std::max<std::size_t>(1, options.checkpointEvery);
    // One piece per thread at least, and more on a big log (balance, smaller fix-ups' share).
    const std::size_t bySize =
            (data.size() + options.pieceBytes - 1) / std::max<std::size_t>(1, options.pieceBytes);
    // A multiple of the threads, so that none is left with one piece more than the others.
    const std::size_t perThread = (std::max<std::size_t>(bySize, threads) + threads - 1) / threads;
    const unsigned wanted =
            static_cast<unsigned>(std::clamp<std::size_t>(perThread * threads, 1, 4096));
    const std::vector<std::string_view> pieces = cutLog(data, std::max(1u, wanted));
    std::vector<PieceRun> runs(pieces.size());
    std::atomic<bool> firstSent{false};

    auto decodePiece = [&](std::size_t k) {
        PieceRun &run = runs[k];
        const std::string_view piece = pieces[k];
        const std::uint64_t pieceStart = offsetOf(base, piece.data());
        reserveRecords(run.records, piece.size() / kBytesPerEpochGuess + 1);
        EpochRunner::Sinks sinks;
        sinks.onEpoch = [&run, &control, &firstSent, k](EpochRecord &&r, const ReceiverState &) {
            if (k == 0 && run.records.empty() && control.onFirstEpoch && !firstSent.exchange(true))
                control.onFirstEpoch(r);
            run.records.push_back(r);
        };
        sinks.onCheckpoint = [&run](Checkpoint &&c) { run.checkpoints.push_back(std::move(c)); };
        EpochRunner runner(registry, options.decoder, base, every, std::move(sinks));
        runner.restore(k == 0 ? from : freshStart(registry, options.decoder, pieceStart));
        if (!runner.feed(piece, control.cancel, control.bytesDone)) {
            if (k != 0 || !control.keepOnCancel) return;
            // Stopped at a line end: the state there is a true checkpoint.
            run.end = runner.save(runner.fedEnd());
            run.framer = runner.framerStats();
            run.partial = true;
            return;
        }
        run.end = runner.save(pieceStart + piece.size());
        run.framer = runner.framerStats();
        run.done = true;
    };
    runPieces(pieces.size(), threads, decodePiece);
    bool cut = false; // cancelled: the index ends after the pieces done from the start
    for (const PieceRun &r : runs) cut |= !r.done;
    if (cut && !(control.keepOnCancel && (runs[0].done || runs[0].partial))) return false;

    // Merge: piece 0 is exact; each later one is checked against the true state at its start.
    out.records.clear();
    out.checkpoints.clear();
    out.start = from.resume;
    out.framer = {};
    addCheckpoint(out.checkpoints, Checkpoint(from));
    std::size_t total = 0;
    for (const PieceRun &r : runs) total += r.records.size();
    out.records = {};
    reserveRecords(out.records, total + 1);
    out.records.insert(out.records.end(), runs[0].records.begin(), runs[0].records.end());
    runs[0].records = {};
    for (auto &c : runs[0].checkpoints) addCheckpoint(out.checkpoints, std::move(c));
    addFramerStats(out.framer, runs[0].framer);
    Checkpoint truth = std::move(runs[0].end);
    for (std::size_t k = 1; k < runs.size() && runs[0].done; ++k) {
        PieceRun &run = runs[k];
        if (!run.done) break; // cancelled: the index ends where piece k starts
        addFramerStats(out.framer, run.framer);
        const std::uint64_t pieceStart = offsetOf(base, pieces[k].data());
        const std::uint64_t pieceEnd = pieceStart + pieces[k].size();
        addCheckpoint(out.checkpoints, Checkpoint(truth));
        EpochRunner::Sinks sinks;
        sinks.onEpoch = [&out](EpochRecord &&r, const ReceiverState &) {
            out.records.push_back(r);
        };
        sinks.onCheckpoint = [&out](Checkpoint &&c) {
            addCheckpoint(out.checkpoints, std::move(c));
        };
        EpochRunner again(registry, options.decoder, base, every, std::move(sinks));
        again.restore(truth);
        std::uint64_t pos = pieceStart;
        bool agreed = false;
        for (std::size_t i = 0; i < run.checkpoints.size() && !agreed; ++i) {
            Checkpoint &c = run.checkpoints[i];
            again.feed(std::string_view(base + pos, c.resume - pos));
            pos = c.resume;
            Checkpoint now = again.save(pos);
            if (!now.sameFuture(c)) continue;
            agreed = true;
            const std::uint64_t local = c.carry.emitted;
            const std::uint64_t shift = now.carry.emitted - local;
            addCheckpoint(out.checkpoints, std::move(now));
            out.records.insert(out.records.end(),
                               run.records.begin() + static_cast<std::ptrdiff_t>(local),
                               run.records.end());
            for (std::size_t j = i + 1; j < run.checkpoints.size(); ++j) {
                run.checkpoints[j].carry.emitted += shift;
                addCheckpoint(out.checkpoints, std::move(run.checkpoints[j]));
            }
            truth = std::move(run.end);
            truth.carry.emitted += shift;
        }
        if (!agreed) {
            again.feed(std::string_view(base + pos, pieceEnd - pos));
            truth = again.save(pieceEnd);
        }
        run = PieceRun(); // memory back as soon as merged
    }
    out.tail = std::move(truth);
    out.indexedEnd = cut ? out.tail.resume : from.resume + data.size();
    closeIndex(base, cut ? std::string_view() : unfinished, registry, options, out);
    if (control.bytesDone && !cut) control.bytesDone->fetch_add(unfinished.size());
    return true;
}

std::size_t extendIndex(const char *base, std::string_view whole, const DialectRegistry &registry,
                        const IndexOptions &options, LogIndex &out) {
    const auto [data, unfinished] = atLastLineEnd(whole);
    // Every record the unfinished line made goes: its bytes are decoded again from the tail. (A
    // line ended by a bare CR, the file cut before its LF, closes an epoch and opens another;
    // dropping the open one alone kept the first twice.)
    out.records.resize(out.records.size() - std::min(out.openRecords, out.records.size()));
    out.checkpoints.resize(out.checkpoints.size() -
                           std::min(out.openCheckpoints, out.checkpoints.size()));
    out.openRecords = out.openCheckpoints = 0;
    out.lastIsOpen = false;
    const std::size_t changedFrom = out.records.size();
    EpochRunner::Sinks sinks;
    sinks.onEpoch = [&out](EpochRecord &&r, const ReceiverState &) { out.records.push_back(r); };
    sinks.onCheckpoint = [&out](Checkpoint &&c) { addCheckpoint(out.checkpoints, std::move(c)); };
    EpochRunner runner(registry, options.decoder, base, options.checkpointEvery, std::move(sinks));
    runner.restore(out.tail);
    runner.feed(data);
    addFramerStats(out.framer, runner.framerStats());
    out.indexedEnd += data.size();
    out.tail = runner.save(out.indexedEnd);
    closeIndex(base, unfinished, registry, options, out);
    return changedFrom;
}

bool stateAtEpoch(const char *base, std::uint64_t dataEnd, const LogIndex &index, std::uint64_t k,
                  const DialectRegistry &registry, const DecoderOptions &options,
                  ReceiverState &out) {
    if (k >= index.records.size()) return false;
    const Checkpoint *cp = index.checkpointFor(k);
    if (!cp) return false;
    bool found = false;
    EpochRunner::Sinks sinks;
    std::uint64_t n = cp->carry.emitted;
    sinks.onEpoch = [&](EpochRecord &&, const ReceiverState &s) {
        if (n++ == k) {
            out = s;
            found = true;
        }
    };
    EpochRunner runner(registry, options, base, index.records.size() + 1, std::move(sinks));
    runner.restore(*cp);
    // Epoch k completes on the first line of epoch k + 1: decode up to that line's end.
    const std::uint64_t limit = std::min(dataEnd, index.openEnd);
    std::uint64_t end = limit;
    if (k + 1 < index.records.size()) {
        const std::uint64_t next = index.records[k + 1].offset;
        std::string_view rest(base + next, end - std::min(end, next));
        const std::size_t eol = rest.find_first_of("\r\n");
        if (eol != std::string_view::npos) end = next + eol + 1;
        if (end < limit && base[end - 1] == '\r' && base[end] == '\n') ++end;
    }
    if (cp->resume > end) return false; // the file was cut short under us
    runner.feed(std::string_view(base + cp->resume, end - cp->resume));
    if (!found && k + 1 == index.records.size()) runner.finish();
    return found;
}

} // namespace gnss::logview
