#pragma once
// scanLog: decode a whole log in memory on several threads and count everything, with the same
// results as one StreamDecoder reading it front to back (what `gnss-cli stats` reports).
//
// The log is cut into segments at line ends; each segment runs its own StreamDecoder and
// EpochAssembler. Framing never depends on earlier bytes across a line end, so framer counts
// simply add up. What can depend on earlier bytes is the dialect recognised in auto mode: a
// segment that began without it while the log before it had named one is corrected by decoding
// the lines before its own detection again with that dialect (or the whole segment, in the rare
// case it never names one itself); these corrections run in parallel too. An epoch cut by a
// segment boundary is counted once.
#include "core/function_ref.h"
#include "core/stream_decoder.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace gnss {

struct LogScanResult {
    FramerStats framer;
    // RTCM 3 frames among the sentences (one pass over the whole log: a cut at a line end may
    // fall inside a frame), and how many of each type; junk: bytes in neither.
    rtcm::RtcmFramerStats rtcm;
    std::map<unsigned, std::uint64_t> rtcmTypes;
    std::uint64_t junkBytes() const {
        return framer.bytesSkipped > rtcm.bytesInFrames ? framer.bytesSkipped - rtcm.bytesInFrames
                                                        : 0;
    }
    std::vector<AddressStats> addresses; // in order of first appearance
    std::uint64_t epochs = 0;
    const Dialect *dialect = nullptr; // the dialect in force at the end
    unsigned segments = 1;            // how many pieces the log was decoded in
    unsigned threads = 1;             // on how many threads
};

// On `threads` threads, in `piecesPerThread` pieces per thread (so that a thread slowed by
// something else takes fewer of them), each at least `minSegmentBytes` long (threads cost more
// than they save on small logs). One thread decodes the log in one piece.
LogScanResult scanLog(std::string_view log, const DialectRegistry &registry,
                      const DecoderOptions &options, unsigned threads,
                      std::size_t minSegmentBytes = 4 << 20, unsigned piecesPerThread = 4);

// Where a line ends for certain, reading `log` alone: just after a LF, after a CR LF, or after
// a CR followed by anything but a LF (a log of CR-ended lines). A CR that is the last byte is not
// an end yet (its LF may follow). A decoder started at such a position frames what one reading
// from the start does.
// The first such position after `from` (npos if none), and the last in `log` (0 if none).
std::size_t lineEndAfter(std::string_view log, std::size_t from);
std::size_t lastLineEnd(std::string_view log);

// The pieces scanLog decodes, for other whole-log passes (the log viewer's index): `log` cut at
// the first line end (above) after each of `pieces` equal shares (fewer when lines are too long).
std::vector<std::string_view> cutLog(std::string_view log, unsigned pieces);

// Calls work(k) once for every k in [0, count), on at most `threads` threads (the caller's
// among them), each taking the next piece when it is done with one.
void runPieces(std::size_t count, unsigned threads, FunctionRef<void(std::size_t)> work);

// Exact merging of per-piece counts.
void addFramerStats(FramerStats &into, const FramerStats &from);
void addAddressStats(std::vector<AddressStats> &into, const std::vector<AddressStats> &from);

} // namespace gnss
