#pragma once
// What an observation message observed, whichever kind it is: an MSM's header or a legacy
// 1001-1004 / 1009-1012 message as one view of system, epoch, satellites and signals, for code
// that needs no more (which systems a stream has, which satellites, when its epochs are).
#include "rtcm/rtcm_messages.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace gnss::rtcm {

struct ObservedSignals {
    System system = System::Gps;
    // GPS-like TOW or GLONASS time of day in ms (as MsmHeader::epochMs); the GLONASS day of week
    // when the message sends it (MSM only).
    std::uint32_t epochMs = 0;
    std::optional<unsigned> gloDayOfWeek;
    bool moreFollow = false;          // MSM DF393, legacy DF005: same epoch, more messages
    std::vector<unsigned> satellites; // satellite ids as sent (MSM ids, GPS PRN, GLONASS slot)
    std::vector<std::string_view> signalNames; // RINEX codes seen, in the message's order; MSM ids
                                               // without a name are left out
};

// The view of a decoded MSM or legacy observables message; none for any other body.
std::optional<ObservedSignals> observedSignals(const RtcmMessage &m);

} // namespace gnss::rtcm
