#pragma once
// MountMonitor: what a served RTCM 3 stream carries, for its source-table record: the message
// types and how often each comes (over the last minute, written as source tables write it:
// "1005(10)" every ten seconds, "1077(1)" every second), the systems and carrier they imply, the
// reference station's id and position (1005/1006, ECEF to WGS-84), and the bit rate. Fed whole,
// CRC-checked frames with the time they were served. Plain C++ (no Qt), never throws.
#include "ntrip/source_table.h"
#include "rtcm/rtcm_framer.h"

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gnss::serve {

struct TypeRate {
    unsigned type = 0;
    std::uint64_t count = 0;             // in the window
    std::optional<double> periodSeconds; // none when seen once in the window
};

class MountMonitor {
public:
    static constexpr std::int64_t kWindowMs = 60000;

    void frame(const rtcm::RtcmFrame &f, std::int64_t nowMs);

    // Every type seen in the last minute, ascending.
    std::vector<TypeRate> rates(std::int64_t nowMs) const;
    // "1005(10),1077(1)": each type with its period in whole seconds (at least 1); a type seen
    // once in the window without a period.
    std::string formatDetails(std::int64_t nowMs) const;
    // "GPS+GLO+GAL": the systems the observation messages are of.
    std::string navSystem(std::int64_t nowMs) const;
    // 0 no observations, 1 L1 only, 2 L1+L2 (MSM or the L1/L2 legacy messages).
    int carrier(std::int64_t nowMs) const;
    // Bits per second over the window (0 before a second of data).
    int bitrate(std::int64_t nowMs) const;
    std::optional<unsigned> station() const { return station_; }
    std::optional<double> latitude() const { return latitude_; }
    std::optional<double> longitude() const { return longitude_; }
    std::uint64_t frames() const { return frames_; }

    // Fills format, format details, carrier, nav system, position and bit rate of `e` from what
    // was served; the other fields are left as they are.
    void describe(ntrip::StreamEntry &e, std::int64_t nowMs) const;

private:
    void prune(std::int64_t nowMs) const;

    mutable std::map<unsigned, std::deque<std::int64_t>> seen_; // type → times in the window
    mutable std::deque<std::pair<std::int64_t, std::size_t>> bytes_;
    std::optional<std::int64_t> first_;
    std::optional<unsigned> station_;
    std::optional<double> latitude_, longitude_;
    std::uint64_t frames_ = 0;
};

} // namespace gnss::serve
