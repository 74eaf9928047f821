// MSM signal ids → RINEX 3 observation codes, per system (RTCM 10403.3 tables 3.5-91 GPS,
// 3.5-96 GLONASS, 3.5-99 Galileo, 3.5-102 SBAS, 3.5-105 QZSS, 3.5-108 BeiDou, NavIC table of
// amendment 2). Ids the tables leave reserved have no name: they are printed by number.
#include "rtcm/rtcm_messages.h"

#include <array>

namespace gnss::rtcm {
namespace {

using Table = std::array<std::string_view, 33>; // index = signal id (1..32); [0] unused

// clang-format off
//                        id:  -     1     2     3     4     5     6     7     8
//                                   9    10    11    12    13    14    15    16
//                                  17    18    19    20    21    22    23    24
//                                  25    26    27    28    29    30    31    32
constexpr Table kGps     = {"",   "",   "1C", "1P", "1W", "",   "",   "",   "2C",
                                  "2P", "2W", "",   "",   "",   "",   "2S", "2L",
                                  "2X", "",   "",   "",   "",   "5I", "5Q", "5X",
                                  "",   "",   "",   "",   "",   "1S", "1L", "1X"};
constexpr Table kGlonass = {"",   "",   "1C", "1P", "",   "",   "",   "",   "2C",
                                  "2P"};
constexpr Table kGalileo = {"",   "",   "1C", "1A", "1B", "1X", "1Z", "",   "6C",
                                  "6A", "6B", "6X", "6Z", "",   "7I", "7Q", "7X",
                                  "",   "8I", "8Q", "8X", "",   "5I", "5Q", "5X"};
constexpr Table kSbas    = {"",   "",   "1C", "",   "",   "",   "",   "",   "",
                                  "",   "",   "",   "",   "",   "",   "",   "",
                                  "",   "",   "",   "",   "",   "5I", "5Q", "5X"};
constexpr Table kQzss    = {"",   "",   "1C", "",   "",   "",   "",   "",   "",
                                  "6S", "6L", "6X", "",   "",   "",   "2S", "2L",
                                  "2X", "",   "",   "",   "",   "5I", "5Q", "5X",
                                  "",   "",   "",   "",   "",   "1S", "1L", "1X"};
constexpr Table kBeiDou  = {"",   "",   "2I", "2Q", "2X", "",   "",   "",   "6I",
                                  "6Q", "6X", "",   "",   "",   "7I", "7Q", "7X",
                                  "",   "",   "",   "",   "",   "5D", "5P", "5X",
                                  "7D", "",   "",   "",   "",   "1D", "1P", "1X"};
constexpr Table kNavIC   = {"",   "",   "",   "",   "",   "",   "",   "",   "",
                                  "",   "",   "",   "",   "",   "",   "",   "",
                                  "",   "",   "",   "",   "",   "5A"};
// clang-format on

const Table &tableOf(System s) {
    switch (s) {
    case System::Gps: return kGps;
    case System::Glonass: return kGlonass;
    case System::Galileo: return kGalileo;
    case System::Sbas: return kSbas;
    case System::Qzss: return kQzss;
    case System::BeiDou: return kBeiDou;
    case System::NavIC: return kNavIC;
    }
    return kGps;
}

} // namespace

std::string_view msmSignalName(System system, unsigned signalId) {
    if (signalId < 1 || signalId > 32) return {};
    return tableOf(system)[signalId];
}

unsigned msmPrn(System system, unsigned satelliteId) {
    switch (system) {
    case System::Sbas: return 119 + satelliteId;
    case System::Qzss: return 192 + satelliteId;
    default: return satelliteId;
    }
}

} // namespace gnss::rtcm
