#pragma once
// RtcmFramer: bytes → RTCM 3 frames.
//
//   +------+----------+--------+-----------------+--------+
//   | 0xD3 | 6 bits 0 | length | payload         | CRC-24Q|
//   | 8    | 6        | 10     | length × 8 bits | 24     |
//   +------+----------+--------+-----------------+--------+
//
// Fed byte chunks of any size, emits each frame whose CRC-24Q (over header and payload) is right.
// Chunking never changes the output: a candidate is judged only once all of its bytes are here,
// so one byte at a time or a megabyte at a time gives the same frames and the same counts.
//
// What is not a frame is counted, never fatal:
//  - bytes outside frames (NMEA text, other binary protocols, noise) → bytesSkipped;
//  - a 0xD3 whose reserved bits are not zero → reservedNonzero; a length above 1023 cannot be
//    written with those bits zero, so this is also the "oversize" count;
//  - a candidate whose CRC is wrong → crcFailures. Only its 0xD3 is skipped and the search goes
//    on from the next byte, so a real frame inside a corrupted (or imagined) one is still found;
//  - the stream ending inside a candidate → truncated (at most once per finish()).
// After finish(): bytesIn == bytesInFrames + bytesSkipped.
#include "core/function_ref.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace gnss::rtcm {

inline constexpr std::uint8_t kPreamble = 0xD3;
inline constexpr std::size_t kMaxPayload = 1023;
inline constexpr std::size_t kFrameOverhead = 6; // 3 header bytes + 3 CRC bytes
inline constexpr std::size_t kMaxFrame = kMaxPayload + kFrameOverhead;

// One checked frame. The bytes are valid only during the callback.
struct RtcmFrame {
    std::span<const std::uint8_t> bytes; // the whole frame: header, payload, CRC
    std::span<const std::uint8_t> payload() const { return bytes.subspan(3, bytes.size() - 6); }
    // DF002, the 12-bit message number; 0 when the payload is shorter than two bytes.
    unsigned messageNumber() const {
        return bytes.size() >= 8 ? (unsigned(bytes[3]) << 4) | (bytes[4] >> 4) : 0;
    }
};

struct RtcmFramerStats {
    std::uint64_t bytesIn = 0;         // every byte fed
    std::uint64_t bytesInFrames = 0;   // bytes of emitted frames (header and CRC included)
    std::uint64_t bytesSkipped = 0;    // bytes outside any emitted frame
    std::uint64_t frames = 0;          // frames emitted (CRC right)
    std::uint64_t crcFailures = 0;     // candidates whose CRC was wrong
    std::uint64_t reservedNonzero = 0; // 0xD3 followed by nonzero reserved bits (or oversize)
    std::uint64_t truncated = 0;       // the stream ended inside a candidate frame
};

class RtcmFramer {
public:
    using FrameCallback = FunctionRef<void(const RtcmFrame &)>;

    void feed(std::string_view chunk, const FrameCallback &onFrame);
    void feed(std::span<const std::uint8_t> chunk, const FrameCallback &onFrame);

    // End of stream: frames still findable in the held bytes are emitted; the rest is skipped.
    void finish(const FrameCallback &onFrame);

    // Forgets held bytes without counting them (e.g. after a reconnect).
    void reset() { held_.clear(); }

    const RtcmFramerStats &stats() const { return stats_; }
    // Bytes held back because they may start a frame not yet complete.
    std::size_t pending() const { return held_.size(); }

private:
    std::size_t scan(const std::uint8_t *p, std::size_t n, std::size_t limit, bool atEnd,
                     const FrameCallback &onFrame);

    RtcmFramerStats stats_;
    std::vector<std::uint8_t> held_; // undecided bytes carried across chunks
    bool truncationCounted_ = false; // this finish() already counted a cut candidate
};

} // namespace gnss::rtcm
