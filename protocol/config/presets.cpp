// Presets: one table. Keys and values are the dialects' schema keys and values; the tests check
// every row against its schema (validateSetting), so a preset cannot drift from the schema.
#include "presets.h"

#include <string>

namespace gnss::config {

namespace {

constexpr PresetValue kNvsRover[] = {
        {"rtk.MODE", "2"},    {"rtk.PVTRATE", "5"},  {"rtk.SYSGPS", "1"},  {"rtk.SYSGLO", "1"},
        {"rtk.SYSSBAS", "1"}, {"rtk.RTCMAGE", "45"}, {"rtk.ICBMODE", "2"}, {"rtk.SFMODE", "3"},
};
constexpr PresetValue kNvsBase[] = {
        {"rtk.MODE", "3"},     {"rtk.AVGTIME", "30"}, {"rtk.AVGMODE", "0"}, {"rtk.RTCMRATE", "1"},
        {"rtk.BASENMEA", "0"}, {"rtk.PVTRATE", "1"},  {"rtk.SYSGPS", "1"},  {"rtk.SYSGLO", "1"},
};
constexpr PresetValue kNvsMovingBase[] = {
        {"rtk.MODE", "4"},   {"rtk.PVTRATE", "5"},   {"rtk.SYSGPS", "1"},
        {"rtk.SYSGLO", "1"}, {"rtk.ICBMBMODE", "2"}, {"rtk.ICBMBTIME", "20"},
};
constexpr PresetValue kGeoStarGpsGlonass[] = {
        {"nav.NVS", "MIX"},  {"output.RATE", "1"}, {"output.NMEAV", "4"}, {"output.GGA", "1"},
        {"output.RMC", "1"}, {"output.GSA", "1"},  {"output.GSV", "1"},
};
constexpr PresetValue kNemerixTracker[] = {
        {"rate.RMC", "1"}, {"rate.GGA", "0"}, {"rate.GLL", "0"}, {"rate.GSA", "0"},
        {"rate.GSV", "0"}, {"rate.VTG", "0"}, {"rate.ZDA", "0"}, {"nmrx.300", "0"},
        {"nmrx.301", "0"}, {"nmrx.302", "0"}, {"nmrx.303", "0"}, {"nmrx.304", "0"},
};

constexpr Preset kPresets[] = {
        {"nvs", "RTK rover 5 Hz",
         "RTK rover at 5 Hz on GPS, GLONASS and SBAS; real-time GLONASS bias calibration, hybrid "
         "secondary filter.",
         kNvsRover},
        {"nvs", "Base station, averaging 30 min",
         "Base station that averages its antenna position for 30 minutes from any valid fix, "
         "then sends RTCM raw data every second.",
         kNvsBase},
        {"nvs", "Moving base with heading",
         "RTK rover with heading (NV08C-RTK-A) at 5 Hz, GLONASS bias calibration for a moving "
         "base.",
         kNvsMovingBase},
        {"geostar", "GPS+GLONASS, 1 Hz, NMEA 4.10",
         "GLONASS and GPS (the GeoS-5 combines them with Galileo: mode MIX), 1 Hz, NMEA 4.10, "
         "GGA, RMC, GSA and GSV on.",
         kGeoStarGpsGlonass},
        {"nemerix", "Minimal output for trackers",
         "RMC once a second and nothing else: the least traffic for a tracker.", kNemerixTracker},
};

} // namespace

std::span<const Preset> presetTable() {
    return kPresets;
}

std::vector<const Preset *> presetsFor(std::string_view dialect) {
    std::vector<const Preset *> out;
    for (const auto &p : kPresets)
        if (p.dialect == dialect) out.push_back(&p);
    return out;
}

std::vector<KeyValue> presetValues(const Preset &p) {
    std::vector<KeyValue> out;
    for (const auto &v : p.values) out.push_back({std::string(v.key), std::string(v.value)});
    return out;
}

} // namespace gnss::config
