#pragma once
// LogIndex: the epochs of a mapped log with checkpoints, built in parallel pieces and merged so
// that it is exactly what one front-to-back decode gives.
//
// How the pieces agree with a front-to-back decode: the log is cut at line ends (cutLog, as
// gnss-cli stats does) and each piece is decoded on its own from an empty state. A piece's
// start can differ from the real thing (the dialect not yet recognised, the sky and the RTK
// status of the epochs before it unknown), so, piece after piece, its start is decoded again
// from the true state at the end of the piece before, up to the piece's first checkpoint where
// both states are the same (StateTracker::sameFuture): from there on, the piece's own epochs and
// checkpoints are exact. A piece that never agrees (a dialect recognised differently, vendor
// state sent once at the start of the log) is decoded again whole: slower, never wrong.
#include "logview/epoch_runner.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace gnss::logview {

struct IndexOptions {
    DecoderOptions decoder;
    unsigned threads = 0;              // 0: one per core
    std::size_t checkpointEvery = 256; // N: a state is rebuilt from at most N epochs
    std::size_t pieceBytes = 64 << 20; // pieces beyond one per thread, for balance
};

struct LogIndex {
    std::vector<EpochRecord> records;        // every epoch, in file order
    std::vector<Checkpoint> checkpoints;     // by carry.emitted, at most N epochs apart
    Checkpoint tail;                         // the state at indexedEnd (to go on when it grows)
    bool lastIsOpen = false;                 // records.back() is the epoch in progress at the end
    std::size_t openRecords = 0;             // records made from the unfinished last line, the
                                             // open one included (more than one when it closes
                                             // an epoch itself: a CR, the file cut before its LF);
                                             // redone when the file grows
    std::size_t openCheckpoints = 0;         // checkpoints.back() ones made from it (after a
                                             // last CR), dropped when it grows
    std::uint64_t start = 0, indexedEnd = 0; // file offsets indexed (to a line end)
    std::uint64_t openEnd = 0;               // ... and with the unfinished last line, if any
    FramerStats framer;                      // bytes, sentences, junk, cut lines (exact)
    FramerStats openFramer;                  // of the unfinished last line (redone as it grows)

    // The checkpoint to rebuild epoch k from: the last one with carry.emitted <= k.
    const Checkpoint *checkpointFor(std::uint64_t k) const;
};

struct IndexControl {
    const std::atomic<bool> *cancel = nullptr;
    std::atomic<std::uint64_t> *bytesDone = nullptr;
    // Called (on a worker thread) with the log's first epoch as soon as it is decoded.
    std::function<void(const EpochRecord &)> onFirstEpoch;
    // Cancelled, buildIndex keeps the exact start it indexed (the first pieces, as far as the
    // first one unfinished, or the first piece up to where it stopped) and returns true: the
    // index then ends short of the data (openEnd), as a log cut there would, and extendIndex
    // goes on from it.
    bool keepOnCancel = false;
};

// The checkpoint that starts a log at `start` (nothing decoded yet).
Checkpoint startOfLog(const DialectRegistry &registry, const DecoderOptions &options,
                      std::uint64_t start);

// Indexes data = [from.resume, from.resume + data.size()) of a mapping whose file offset 0 is
// `base`, from the state `from` (startOfLog for a whole log). Bytes after the last line end (a
// line still being written, or cut) are decoded into the last epoch but not into `tail`, so
// that following the file picks the line up whole. False when cancelled (see keepOnCancel).
bool buildIndex(const char *base, std::string_view data, const Checkpoint &from,
                const DialectRegistry &registry, const IndexOptions &options, LogIndex &out,
                const IndexControl &control = {});

// Goes on indexing what a growing file has gained: data = [out.indexedEnd, new end). The open
// last epoch is replaced by what it has become. Returns the first record index that changed.
std::size_t extendIndex(const char *base, std::string_view data, const DialectRegistry &registry,
                        const IndexOptions &options, LogIndex &out);

// The receiver state at epoch k, exactly as a front-to-back decode has it when epoch k
// completes: decoded from the checkpoint before it (at most N epochs). `data` is the whole
// mapping up to the indexed end. False when k is out of range or the bytes are gone.
bool stateAtEpoch(const char *base, std::uint64_t dataEnd, const LogIndex &index, std::uint64_t k,
                  const DialectRegistry &registry, const DecoderOptions &options,
                  ReceiverState &out);

} // namespace gnss::logview
