#pragma once
// scanLog: decode a whole log in memory on several threads and count everything, with the same
// results as one StreamDecoder reading it front to back (what `gnss-cli stats` reports).
//
// The log is cut into segments at line ends; each segment runs its own StreamDecoder and
// EpochAssembler. Framing never depends on earlier bytes across a line end, so framer counts
// simply add up. What can depend on earlier bytes is the dialect recognised in auto mode: a
// segment that began without it while the log before it had named one is corrected by decoding
// the lines before its own detection again with that dialect (or the whole segment, in the rare
// case it never names one itself). An epoch cut by a segment boundary is counted once.
#include "core/stream_decoder.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace gnss {

struct LogScanResult {
    FramerStats framer;
    std::vector<AddressStats> addresses; // in order of first appearance
    std::uint64_t epochs = 0;
    const Dialect *dialect = nullptr; // the dialect in force at the end
    unsigned segments = 1;            // how many pieces were decoded in parallel
};

// `threads` pieces at most, each at least `minSegmentBytes` long (threads cost more than they
// save on small logs).
LogScanResult scanLog(std::string_view log, const DialectRegistry &registry,
                      const DecoderOptions &options, unsigned threads,
                      std::size_t minSegmentBytes = 4 << 20);

} // namespace gnss
