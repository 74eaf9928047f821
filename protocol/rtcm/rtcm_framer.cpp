#include "rtcm/rtcm_framer.h"

#include "rtcm/crc24q.h"

#include <algorithm>
#include <cstring>

namespace gnss::rtcm {

// Judges every candidate 0xD3 at an offset below `limit` in p[0, n). Returns the offset of the
// first byte not yet decided: a candidate that needs bytes beyond n (never when atEnd), or
// `limit` or more when everything before it was decided. A frame found may end beyond `limit`.
std::size_t RtcmFramer::scan(const std::uint8_t *p, std::size_t n, std::size_t limit, bool atEnd,
                             const FrameCallback &onFrame) {
    std::size_t i = 0;
    while (i < limit) {
        const void *hit = std::memchr(p + i, kPreamble, limit - i);
        if (!hit) {
            stats_.bytesSkipped += limit - i;
            return limit;
        }
        const auto j = static_cast<std::size_t>(static_cast<const std::uint8_t *>(hit) - p);
        stats_.bytesSkipped += j - i;
        i = j;

        const std::size_t avail = n - i;
        if (avail >= 2 && (p[i + 1] & 0xFC) != 0) {
            ++stats_.reservedNonzero;
            ++stats_.bytesSkipped;
            ++i;
            continue;
        }
        const std::size_t length =
                avail >= 3 ? (std::size_t(p[i + 1] & 0x03) << 8) | p[i + 2] : kMaxPayload;
        const std::size_t total = length + kFrameOverhead;
        if (avail < 3 || avail < total) {
            if (!atEnd) return i; // wait for the rest
            // The stream ended inside this candidate; what follows its 0xD3 may still hold a
            // whole frame (the candidate may be imagined), so look on from the next byte.
            if (!truncationCounted_) {
                ++stats_.truncated;
                truncationCounted_ = true;
            }
            ++stats_.bytesSkipped;
            ++i;
            continue;
        }
        const std::uint8_t *f = p + i;
        const std::uint32_t sent = (std::uint32_t(f[total - 3]) << 16) |
                                   (std::uint32_t(f[total - 2]) << 8) | f[total - 1];
        if (crc24q(f, total - 3) != sent) {
            ++stats_.crcFailures;
            ++stats_.bytesSkipped;
            ++i;
            continue;
        }
        ++stats_.frames;
        stats_.bytesInFrames += total;
        onFrame(RtcmFrame{std::span<const std::uint8_t>(f, total)});
        i += total;
    }
    return i;
}

void RtcmFramer::feed(std::string_view chunk, const FrameCallback &onFrame) {
    feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(chunk.data()),
                                       chunk.size()),
         onFrame);
}

void RtcmFramer::feed(std::span<const std::uint8_t> chunk, const FrameCallback &onFrame) {
    stats_.bytesIn += chunk.size();
    std::size_t from = 0; // first byte of `chunk` still to scan in place
    if (!held_.empty()) {
        // Judge the held candidates with just enough new bytes: any candidate starting in the
        // held part ends within kMaxFrame bytes of it, so copying more would be wasted.
        const std::size_t old = held_.size();
        const std::size_t take = std::min(chunk.size(), kMaxFrame);
        held_.insert(held_.end(), chunk.begin(), chunk.begin() + std::ptrdiff_t(take));
        const std::size_t done = scan(held_.data(), held_.size(), old, false, onFrame);
        if (done < old) {
            // Still undecided: only possible when the whole chunk fitted in `take`.
            held_.erase(held_.begin(), held_.begin() + std::ptrdiff_t(done));
            return;
        }
        from = done - old;
        held_.clear();
    }
    const std::size_t n = chunk.size() - from;
    const std::size_t done = scan(chunk.data() + from, n, n, false, onFrame);
    if (done < n) held_.assign(chunk.begin() + std::ptrdiff_t(from + done), chunk.end());
}

void RtcmFramer::finish(const FrameCallback &onFrame) {
    truncationCounted_ = false;
    if (!held_.empty()) scan(held_.data(), held_.size(), held_.size(), true, onFrame);
    held_.clear();
}

} // namespace gnss::rtcm
