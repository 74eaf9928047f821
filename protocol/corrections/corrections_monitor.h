#pragma once
// CorrectionsMonitor: what the corrections stream holds and how healthy it is, for the GUI's
// corrections panel and for tests. Fed the bytes a CorrectionSource delivers, with the time
// they arrived (ms of any monotonic clock: the caller's, so tests use a fake one):
//
//   - per message type: count, rate (messages/s over the last 10 s), time of the last and its
//     age, a one-line meaning ("1074: GPS MSM4"), decode errors;
//   - bytes/s, CRC errors and skipped bytes (gnss_rtcm's framer counts);
//   - the base position from 1005/1006 (ECEF and latitude/longitude/height) and, given the
//     rover's position, the baseline length;
//   - the age of the corrections (since the last observation message) and a bounded history
//     of it for a chart (sampleAge() once a second keeps the last 10 minutes).
//
// Plain C++ on gnss_rtcm (no Qt): whoever owns it decides when to sample and repaint.
#include "core/wgs84.h"
#include "rtcm/rtcm_stream_decoder.h"

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::corrections {

struct MessageTypeStats {
    unsigned number = 0;
    std::string meaning; // "base position"
    std::string line;    // "1005: base position"
    std::uint64_t count = 0;
    std::uint64_t bytes = 0;        // whole frames
    std::uint64_t decodeErrors = 0; // frames of this type that did not decode whole
    double ratePerSecond = 0;       // over the last 10 s (less when younger)
    std::int64_t lastMs = 0;        // when the last arrived
    std::int64_t ageMs = 0;         // now − lastMs
};

struct BasePosition {
    unsigned station = 0;
    unsigned message = 0; // 1005 or 1006
    wgs84::Ecef ecef;
    std::optional<wgs84::Geodetic> geodetic;
    std::optional<double> antennaHeight; // 1006
    std::int64_t receivedMs = 0;
};

struct AgeSample {
    std::int64_t atMs = 0;
    std::optional<std::int64_t> ageMs; // none before the first observation message
};

class CorrectionsMonitor {
public:
    static constexpr std::int64_t kRateWindowMs = 10000;
    static constexpr std::size_t kHistoryLength = 600;

    void feed(std::string_view bytes, std::int64_t nowMs);
    // Forgets everything (another source was chosen). The rover position is kept.
    void reset();

    // Every type seen, ascending by number.
    std::vector<MessageTypeStats> messageTypes(std::int64_t nowMs) const;
    std::optional<MessageTypeStats> messageType(unsigned number, std::int64_t nowMs) const;
    std::uint64_t messages() const { return messages_; }
    std::uint64_t bytesTotal() const { return decoder_.framerStats().bytesIn; }
    double bytesPerSecond(std::int64_t nowMs) const { return byteRate_.rate(nowMs); }
    std::uint64_t crcErrors() const { return decoder_.framerStats().crcFailures; }
    std::uint64_t bytesSkipped() const { return decoder_.framerStats().bytesSkipped; }
    std::uint64_t decodeErrors() const { return decoder_.decodeErrors(); }
    const rtcm::RtcmFramerStats &framerStats() const { return decoder_.framerStats(); }

    const std::optional<BasePosition> &basePosition() const { return base_; }
    void setRoverPosition(const wgs84::Geodetic &rover);
    void clearRoverPosition() { rover_.reset(); }
    // Straight-line distance from the rover to the base's antenna reference point, metres.
    std::optional<double> baselineMetres() const;

    // Since the last observation message (MSM, 1001-1004, 1009-1012); none before the first.
    std::optional<std::int64_t> correctionAgeMs(std::int64_t nowMs) const;
    // Since the last message of any type.
    std::optional<std::int64_t> lastMessageAgeMs(std::int64_t nowMs) const;
    // Records the correction age now (call at a steady pace, e.g. once a second).
    void sampleAge(std::int64_t nowMs);
    const std::deque<AgeSample> &ageHistory() const { return history_; }

private:
    // Counts in one-second buckets over the last ten seconds.
    struct RateCounter {
        std::array<std::uint64_t, 10> counts{};
        std::array<std::int64_t, 10> seconds{};
        std::optional<std::int64_t> firstSecond;
        void add(std::int64_t nowMs, std::uint64_t n);
        double rate(std::int64_t nowMs) const;
    };
    struct TypeState {
        std::uint64_t count = 0, bytes = 0, decodeErrors = 0;
        std::int64_t lastMs = 0;
        RateCounter rate;
    };
    void onMessage(const rtcm::RtcmMessage &m, std::int64_t nowMs);
    MessageTypeStats statsOf(unsigned number, const TypeState &t, std::int64_t nowMs) const;

    rtcm::RtcmStreamDecoder decoder_;
    std::map<unsigned, TypeState> types_;
    RateCounter byteRate_;
    std::uint64_t messages_ = 0;
    std::optional<std::int64_t> lastObservationMs_, lastMessageMs_;
    std::optional<BasePosition> base_;
    std::optional<wgs84::Ecef> rover_;
    std::deque<AgeSample> history_;
};

} // namespace gnss::corrections
