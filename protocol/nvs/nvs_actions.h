#pragma once
// NV08C-RTK receiver-wide actions, presets and link speeds, as data of the dialect record.
//   4.8 PNVGCFG: W saves the settings to flash; R erases them and restarts with the defaults.
//   4.3 PNVGRST: F cold start, W warm restart (settings kept).
//   4.11 PNVGRZA,<port>,<baud>,<protocol>: the host is on COM1.
#include "core/dialect.h"

namespace gnss::nvs {

inline constexpr ActionDef kActions[] = {
        {ReceiverAction::SaveToFlash, "PNVGCFG,W", "Save to flash",
         "The settings in force are written to flash and survive a power cycle."},
        {ReceiverAction::RestoreDefaults, "PNVGCFG,R", "Restore defaults",
         "The saved settings are erased and the receiver restarts with the factory defaults."},
        {ReceiverAction::ColdStart, "PNVGRST,F", "Cold start",
         "The receiver restarts without almanac or ephemeris; settings are kept."},
        {ReceiverAction::WarmStart, "PNVGRST,W", "Warm start",
         "The receiver restarts with its almanac; settings are kept."},
};

// Table 1: 4,800 to 460,800 bit/s.
// Table 1 / section 1.1: what the receiver runs at from the factory.
inline constexpr int kDefaultBaud = 115200;
inline constexpr int kSupportedBauds[] = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800};

inline constexpr PresetValue kRover[] = {
        {"rtk.MODE", "2"},    {"rtk.PVTRATE", "5"},  {"rtk.SYSGPS", "1"},  {"rtk.SYSGLO", "1"},
        {"rtk.SYSSBAS", "1"}, {"rtk.RTCMAGE", "45"}, {"rtk.ICBMODE", "2"}, {"rtk.SFMODE", "3"},
};
inline constexpr PresetValue kBase[] = {
        {"rtk.MODE", "3"},     {"rtk.AVGTIME", "30"}, {"rtk.AVGMODE", "0"}, {"rtk.RTCMRATE", "1"},
        {"rtk.BASENMEA", "0"}, {"rtk.PVTRATE", "1"},  {"rtk.SYSGPS", "1"},  {"rtk.SYSGLO", "1"},
};
inline constexpr PresetValue kMovingBase[] = {
        {"rtk.MODE", "4"},   {"rtk.PVTRATE", "5"},   {"rtk.SYSGPS", "1"},
        {"rtk.SYSGLO", "1"}, {"rtk.ICBMBMODE", "2"}, {"rtk.ICBMBTIME", "20"},
};
inline constexpr Preset kPresets[] = {
        {"RTK rover 5 Hz",
         "RTK rover at 5 Hz on GPS, GLONASS and SBAS; real-time GLONASS bias calibration, hybrid "
         "secondary filter.",
         kRover},
        {"Base station, averaging 30 min",
         "Base station that averages its antenna position for 30 minutes from any valid fix, "
         "then sends RTCM raw data every second.",
         kBase},
        {"Moving base with heading",
         "RTK rover with heading (NV08C-RTK-A) at 5 Hz, GLONASS bias calibration for a moving "
         "base.",
         kMovingBase},
};

} // namespace gnss::nvs
