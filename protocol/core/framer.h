#pragma once
// Framer: bytes → NMEA sentences.
//
// Fed byte chunks of any size, emits each sentence that starts at '$' or '!' and ends at CR LF,
// LF or CR (the terminator is not part of the emitted view). Chunking never changes the output:
// one byte at a time or a megabyte at a time gives the same sentences.
//
// What is not a sentence is counted, never fatal:
//  - bytes between sentences (RTCM3, UBX, vendor binary, banners) → bytesSkipped;
//  - a line longer than kMaxLine bytes → dropped, tooLong++, resynchronise at the next '$'/'!';
//  - a '$' or '!' inside a sentence starts a new one; the cut one → truncated++;
//  - a byte that cannot be in an NMEA sentence (control or 8-bit) inside a sentence means we were
//    not in a sentence at all (binary data that happened to contain 0x24): the bytes are counted
//    as skipped binary and we resynchronise → binaryAborted++.
#include "core/function_ref.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gnss {

struct FramerStats {
    std::uint64_t bytesIn = 0;       // every byte fed
    std::uint64_t bytesSkipped = 0;  // bytes outside any emitted sentence (incl. dropped lines)
    std::uint64_t sentences = 0;     // sentences emitted
    std::uint64_t truncated = 0;     // sentences cut by a new '$'/'!' before their end
    std::uint64_t tooLong = 0;       // lines dropped for exceeding kMaxLine
    std::uint64_t binaryAborted = 0; // sentence candidates abandoned on a non-text byte
};

class Framer {
public:
    static constexpr std::size_t kMaxLine = 4096;
    using SentenceCallback = FunctionRef<void(std::string_view)>;

    // Feeds a chunk; calls onSentence for each complete sentence. Views passed to the callback
    // are valid only during the call.
    void feed(std::string_view chunk, const SentenceCallback &onSentence);

    // End of stream: a pending partial sentence is counted as truncated and dropped.
    void finish();

    // Drops any partial sentence without counting it (e.g. after a reconnect or a seek).
    void reset();

    const FramerStats &stats() const { return stats_; }
    bool inSentence() const { return inSentence_; }

private:
    void abandon(std::size_t bytes);

    FramerStats stats_;
    std::string pending_; // partial sentence carried across chunks
    bool inSentence_ = false;
    bool pendingCr_ = false; // last byte of previous chunk was CR: a following LF is its pair
};

} // namespace gnss
