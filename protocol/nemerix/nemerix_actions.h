#pragma once
// VT002 receiver-wide actions, presets and port speeds, as data of the dialect record.
//   PNMRX111: FACTORY / COLD / WARM / HOT; the VT002 has no save command.
//   PNMRX100: 1200 to 57600 bit/s.
#include "core/dialect.h"

namespace gnss::nemerix {

inline constexpr ActionDef kActions[] = {
        {ReceiverAction::RestoreDefaults, "PNMRX111,FACTORY", "Restore defaults",
         "The receiver returns to its factory settings and restarts."},
        {ReceiverAction::ColdStart, "PNMRX111,COLD", "Cold start",
         "The receiver restarts without almanac or ephemeris."},
        {ReceiverAction::WarmStart, "PNMRX111,WARM", "Warm start",
         "The receiver restarts with its almanac."},
        {ReceiverAction::HotStart, "PNMRX111,HOT", "Hot start",
         "The receiver restarts with almanac and ephemeris."},
};

inline constexpr int kDefaultBaud = 9600;
inline constexpr int kSupportedBauds[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600};

inline constexpr PresetValue kTracker[] = {
        {"rate.RMC", "1"}, {"rate.GGA", "0"}, {"rate.GLL", "0"}, {"rate.GSA", "0"},
        {"rate.GSV", "0"}, {"rate.VTG", "0"}, {"rate.ZDA", "0"}, {"nmrx.300", "0"},
        {"nmrx.301", "0"}, {"nmrx.302", "0"}, {"nmrx.303", "0"}, {"nmrx.304", "0"},
};
inline constexpr Preset kPresets[] = {
        {"Minimal output for trackers",
         "RMC once a second and nothing else: the least traffic for a tracker.", kTracker},
};

} // namespace gnss::nemerix
