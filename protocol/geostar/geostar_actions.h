#pragma once
// GeoS-5 receiver-wide actions, presets and port speeds, as data of the dialect record.
//   4.2 SAVEFL writes the almanacs and the settings in force to flash; 4.3-4.5 CSTART / WSTART /
//   HSTART; no command restores the defaults. 4.8 BDR004..BDR921.
#include "core/dialect.h"

namespace gnss::geostar {

inline constexpr ActionDef kActions[] = {
        {ReceiverAction::SaveToFlash, "GPSGG,SAVEFL", "Save to flash",
         "The almanacs and the settings in force are written to flash."},
        {ReceiverAction::ColdStart, "GPSGG,CSTART", "Cold start",
         "The receiver restarts without almanac or ephemeris."},
        {ReceiverAction::WarmStart, "GPSGG,WSTART", "Warm start",
         "The receiver restarts with its almanac."},
        {ReceiverAction::HotStart, "GPSGG,HSTART", "Hot start",
         "The receiver restarts with almanac and ephemeris."},
};

// The spec names no factory speed; 115200 bit/s (BDR115) is an assumption.
inline constexpr int kDefaultBaud = 115200;
inline constexpr int kSupportedBauds[] = {4800,   9600,   19200,  38400, 57600,
                                          115200, 230400, 460800, 921600};

inline constexpr PresetValue kGpsGlonass[] = {
        {"nav.NVS", "MIX"},  {"output.RATE", "1"}, {"output.NMEAV", "4"}, {"output.GGA", "1"},
        {"output.RMC", "1"}, {"output.GSA", "1"},  {"output.GSV", "1"},
};
inline constexpr Preset kPresets[] = {
        {"GPS+GLONASS, 1 Hz, NMEA 4.10",
         "GLONASS and GPS (the GeoS-5 combines them with Galileo: mode MIX), 1 Hz, NMEA 4.10, "
         "GGA, RMC, GSA and GSV on.",
         kGpsGlonass},
};

} // namespace gnss::geostar
