#include "corrections/rtcm_message_names.h"

#include "rtcm/rtcm_messages.h"

#include <string_view>

namespace gnss::corrections {

namespace {

struct Name {
    unsigned number;
    std::string_view meaning;
};

// The messages a receiver user meets; RTCM 10403.3 table 3.5-1 has the full list.
constexpr Name kNames[] = {
        {1001, "GPS L1 observations"},
        {1002, "GPS L1 observations, extended"},
        {1003, "GPS L1/L2 observations"},
        {1004, "GPS L1/L2 observations, extended"},
        {1005, "base position"},
        {1006, "base position and antenna height"},
        {1007, "antenna descriptor"},
        {1008, "antenna descriptor and serial number"},
        {1009, "GLONASS L1 observations"},
        {1010, "GLONASS L1 observations, extended"},
        {1011, "GLONASS L1/L2 observations"},
        {1012, "GLONASS L1/L2 observations, extended"},
        {1013, "system parameters"},
        {1019, "GPS ephemeris"},
        {1020, "GLONASS ephemeris"},
        {1029, "text message"},
        {1033, "receiver and antenna descriptors"},
        {1042, "BeiDou ephemeris"},
        {1044, "QZSS ephemeris"},
        {1045, "Galileo F/NAV ephemeris"},
        {1046, "Galileo I/NAV ephemeris"},
        {1057, "GPS SSR orbit corrections"},
        {1058, "GPS SSR clock corrections"},
        {1063, "GLONASS SSR orbit corrections"},
        {1064, "GLONASS SSR clock corrections"},
        {1230, "GLONASS biases"},
        {4072, "u-blox proprietary"},
        {4094, "Trimble proprietary"},
};

} // namespace

std::string rtcmMessageMeaning(unsigned number) {
    if (rtcm::isMsm(number)) {
        const auto system = static_cast<rtcm::System>((number - 1071) / 10);
        return std::string(rtcm::systemName(system)) + " MSM" + std::to_string(number % 10);
    }
    for (const Name &n : kNames)
        if (n.number == number) return std::string(n.meaning);
    if (number >= 4001 && number <= 4095) return "proprietary";
    return "message " + std::to_string(number);
}

std::string describeRtcmMessage(unsigned number) {
    return std::to_string(number) + ": " + rtcmMessageMeaning(number);
}

bool isObservationMessage(unsigned number) {
    return rtcm::isMsm(number) || (number >= 1001 && number <= 1004) ||
           (number >= 1009 && number <= 1012);
}

} // namespace gnss::corrections
