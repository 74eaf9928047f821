#pragma once
// RtcmStreamDecoder: bytes in, decoded RTCM messages out, everything counted.
//
//   bytes → RtcmFramer → decodeMessage → handler
//
// Like the NMEA StreamDecoder: never throws, never stops; a frame whose payload cannot be read
// whole is still handed over (with its error) and counted.
#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_messages.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace gnss::rtcm {

class RtcmStreamDecoder {
public:
    using Handler = FunctionRef<void(const RtcmMessage &)>;

    void feed(std::string_view bytes, const Handler &handler);
    void finish(const Handler &handler);

    const RtcmFramerStats &framerStats() const { return framer_.stats(); }
    std::uint64_t decodeErrors() const { return decodeErrors_; }
    // Frames per message number, ascending by number (0: frames too short to carry one).
    std::vector<std::pair<unsigned, std::uint64_t>> typeCounts() const;

private:
    void onFrame(const RtcmFrame &f, const Handler &handler);

    RtcmFramer framer_;
    std::array<std::uint64_t, 4096> perType_{};
    std::uint64_t decodeErrors_ = 0;
};

} // namespace gnss::rtcm
