#pragma once
// When to send each part of a recorded RTCM file so it plays at the pace it was recorded.
//
// Frames are grouped by epoch: an MSM's epoch time (GPS/Galileo/QZSS/SBAS/NavIC and BeiDou time
// of week, GLONASS time of day) moves that system's clock; a group starts where any system's
// clock moves past the current group's time, so the GPS and GLONASS MSMs of one epoch travel
// together although their clocks differ by hours. Other frames (1005, ephemerides, 1230) go
// with the group they follow. A file without MSMs is paced by its 1005/1006 frames, one second
// apart; a file with neither is sent at once. Gaps are capped at a minute and a clock going
// backwards (files joined together) counts as one second. Bytes between frames travel with
// the group before them, so the file is sent whole and byte-exact. Plain C++, no Qt.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace gnss::corrections {

struct PlaybackGroup {
    std::size_t begin = 0; // byte range in the file: [begin, end)
    std::size_t end = 0;
    std::int64_t atMs = 0; // when to send it, from the start of playback at speed 1
    std::size_t frames = 0;
};

struct PlaybackPlan {
    enum class Timing { Msm, StationMessages, AllAtOnce };
    std::vector<PlaybackGroup> groups;
    Timing timing = Timing::AllAtOnce;
    std::size_t frames = 0; // RTCM frames found (CRC right)
    std::size_t crcFailures = 0;
    std::int64_t durationMs() const { return groups.empty() ? 0 : groups.back().atMs; }
};

inline constexpr std::int64_t kMaxPlaybackGapMs = 60000;

PlaybackPlan planPlayback(std::string_view file);

} // namespace gnss::corrections
