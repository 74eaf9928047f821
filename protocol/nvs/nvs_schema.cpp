// The NVS settings schema: every configurable parameter of the NV08C-RTK, as data.
// Labels, ranges, defaults and help are the spec's (nvs-nv08c-rtk-nmea-v1.6.txt); where the spec
// gives no range the row says what was inferred and from what.
#include "nvs/nvs_schema.h"

namespace gnss::nvs {
namespace {

using O = SettingOption;
using T = SettingType;
constexpr auto kNone = std::nullopt;

constexpr O kOnOff[] = {{"0", "Off"}, {"1", "On"}};
using M = OptionMeaning;
constexpr O kMode[] = {
        {"0", "Autonomous", M::Autonomous},
        {"1", "Base station", M::BaseFixed},
        {"2", "RTK rover", M::Rover},
        {"3", "Base station with automatic antenna position averaging", M::BaseAveraging},
        {"4", "RTK rover + heading (NV08C-RTK-A only)", M::Rover}};
constexpr O kPvtRate[] = {{"1", "1 Hz"}, {"2", "2 Hz"}, {"5", "5 Hz"}, {"10", "10 Hz"}};
constexpr O kRtcmRate[] = {{"0", "Same as PVT rate"},
                           {"1", "Every 1 s"},
                           {"2", "Every 2 s"},
                           {"5", "Every 5 s"},
                           {"10", "Every 10 s"}};
constexpr O kBaseNmea[] = {{"0", "Base coordinates", M::BasePosition},
                           {"1", "Current 3D coordinates", M::OwnPosition}};
constexpr O kAvgMode[] = {
        {"0", "Any valid coordinates"}, {"1", "Fixed & Float"}, {"2", "Fixed only"}};
constexpr O kSfMode[] = {{"0", "Disable"}, {"1", "Retain"}, {"2", "Transition"}, {"3", "Hybrid"}};
constexpr O kIcbMode[] = {{"0", "Off"},
                          {"1", "Initial calibration (GPS as reference)"},
                          {"2", "Real-time recalibration"}};
constexpr O kProtocol[] = {
        {"0", "Disabled", M::Off}, {"1", "NMEA 0183", M::Nmea}, {"7", "RTCM", M::Rtcm3}};
constexpr O kTalker[] = {{"0", "GGA and RMC talker always GP"},
                         {"1", "Compatibility off: talker as specified"}};
constexpr O kPpsType[] = {{"P", "Software-synchronised"},
                          {"A", "Hardware-synchronised (aligned to internal timescale)"}};
constexpr O kPpsMode[] = {{"I", "Interval: pulse at PVT update rate"}, {"S", "1PPS"}};
constexpr O kPpsRef[] = {{"U", "UTC"}, {"S", "UTC(SU)"}, {"G", "GLONASS time"}, {"N", "GPS time"}};
constexpr O kPpsValid[] = {{"E", "Enabled"}, {"D", "Disabled"}};
constexpr O kIdlMode[] = {{"0", "Any base station"}, {"1", "Only base stations from the list"}};

constexpr std::string_view kRtk = "RTK engine";

// One PNVGRTK row: key "rtk.NAME", read back by naming the parameter without a value.
#define RTK_ROLE(NAME, LABEL, TYPE, UNIT, MIN, MAX, OPTS, DEF, HELP, ROLE)                         \
    SettingDef {                                                                                   \
        .key = "rtk." NAME, .label = LABEL, .group = kRtk, .type = TYPE, .unit = UNIT, .min = MIN, \
        .max = MAX, .options = OPTS, .defaultValue = DEF, .help = HELP,                            \
        .readBack = "$PNVGRTK," NAME " -> $PNVGRTK," NAME ",<value>",                              \
        .write = "$PNVGRTK," NAME ",<value>", .command = &kRtkCommand, .role = ROLE                \
    }
#define RTK(NAME, LABEL, TYPE, UNIT, MIN, MAX, OPTS, DEF, HELP)                                    \
    RTK_ROLE(NAME, LABEL, TYPE, UNIT, MIN, MAX, OPTS, DEF, HELP, SettingRole::None)

// The two settings of one port are one command (PNVGRZA,N): always sent together.
#define PORT(N, NAME, SPEED_ROLE)                                                                  \
    SettingDef{.key = "port." NAME ".baud",                                                        \
               .label = NAME " baud rate",                                                         \
               .group = "Ports",                                                                   \
               .type = T::Integer,                                                                 \
               .unit = "bit/s",                                                                    \
               .min = 4800,                                                                        \
               .max = 460800,                                                                      \
               .defaultValue = "115200",                                                           \
               .help = "Port baud rate, in bauds from 4,800 to 460,800 (115,200 by default, "      \
                       "Table 1). The receiver answers with PNVGRZA and then switches.",           \
               .access = SettingAccess::WriteOnly,                                                 \
               .readBack = "none documented (PNVGRZA answers only when set)",                      \
               .write = "$PNVGRZA," N ",<baud>,<protocol>",                                        \
               .command = &kPortCommands[N[0] - '1'],                                              \
               .role = SPEED_ROLE,                                                                 \
               .port = N[0] - '0'},                                                                \
            SettingDef {                                                                           \
        .key = "port." NAME ".protocol", .label = NAME " protocol", .group = "Ports",              \
        .type = T::Enum, .options = kProtocol, .defaultValue = "1",                                \
        .help = "Protocol type: 0 disable, 1 NMEA 0183, 7 RTCM. Sent together with the baud "      \
                "rate.",                                                                           \
        .access = SettingAccess::WriteOnly,                                                        \
        .readBack = "none documented (PNVGRZA answers only when set)",                             \
        .write = "$PNVGRZA," N ",<baud>,<protocol>", .command = &kPortCommands[N[0] - '1'],        \
        .role = SettingRole::PortProtocol, .port = N[0] - '0'                                      \
    }

#define OUTPUT(N, NAME)                                                                            \
    SettingDef {                                                                                   \
        .key = "output." NAME, .label = NAME " output messages", .group = "Output",                \
        .type = T::List,                                                                           \
        .help = "Messages transmitted on " NAME " and their output rates in PVT "                  \
                "update intervals, as ADDRESS:RATE items separated by ';' "                        \
                "(\"RMC:1;GSV:5;PNVGTST:10\"); at most 20 messages. Written as "                   \
                "a clear followed by one add.",                                                    \
        .access = SettingAccess::WriteOnly, .readBack = "none documented",                         \
        .write = "$PNVGRZB,PORT," N " then $PNVGRZB,PORT," N ",<address>,<rate>,...",              \
        .command = &kOutputCommands[N[0] - '1']                                                    \
    }

// One PNVGNME row (4.2): the three fields are one command, answered only when set; TALKER is how
// the command template shows the optional talker mode.
#define NME(NAME, LABEL, TYPE, MIN, MAX, OPTS, DEF, HELP, TALKER)                                  \
    SettingDef {                                                                                   \
        .key = "nmea." NAME, .label = LABEL, .group = "NMEA output", .type = TYPE, .min = MIN,     \
        .max = MAX, .options = OPTS, .defaultValue = DEF, .help = HELP,                            \
        .access = SettingAccess::WriteOnly,                                                        \
        .readBack = "none documented (PNVGNME answers only when set)",                             \
        .write = "$PNVGNME,<time decimals>,<position decimals>" TALKER, .command = &kNmeCommand    \
    }

// One PNVGPPS row (4.9): the seven fields are one command, read back by sending it empty;
// READ_BACK says where the value is in the reply.
#define PPS(NAME, LABEL, TYPE, UNIT, MIN, MAX, OPTS, DEF, HELP, READ_BACK, WRITE)                  \
    SettingDef {                                                                                   \
        .key = "pps." NAME, .label = LABEL, .group = "Time pulse", .type = TYPE, .unit = UNIT,     \
        .min = MIN, .max = MAX, .options = OPTS, .defaultValue = DEF, .help = HELP,                \
        .readBack = "$PNVGPPS,,,,,,, -> " READ_BACK, .write = WRITE, .command = &kPpsCommand       \
    }

const SettingDef kSchema[] = {
        // ---- 4.14 PNVGRTK, Table 4 (33 parameters, in the spec's order) ----
        RTK_ROLE("MODE", "Operation mode", T::Enum, "", kNone, kNone, kMode, "2",
                 "Setting of operation mode: 0 Autonomous, 1 Base Station, 2 RTK-Rover (by "
                 "default), "
                 "3 Base Station with automatic antenna position averaging, 4 RTK Rover + Heading "
                 "(NV08C-RTK-A only).",
                 SettingRole::BaseMode),
        RTK_ROLE("PVTRATE", "PVT rate", T::Enum, "Hz", kNone, kNone, kPvtRate, "5",
                 "PVT rate, Hz (1, 2, 5 by default, 10).", SettingRole::OutputRate),
        RTK("SYSGPS", "Use GPS", T::Bool, "", kNone, kNone, kOnOff, "1",
            "1 - GPS ON (by default), 0 - GPS OFF."),
        RTK("SYSGLO", "Use GLONASS", T::Bool, "", kNone, kNone, kOnOff, "1",
            "1 - GLONASS ON (by default), 0 - GLONASS OFF."),
        RTK("SYSSBAS", "Use SBAS", T::Bool, "", kNone, kNone, kOnOff, "1",
            "1 - SBAS ON (by default), 0 - SBAS OFF."),
        RTK_ROLE("ELGPS", "GPS elevation mask (RTK)", T::Integer, "deg", 0, 90, {}, "5",
                 "GPS Elevation Mask for RTK mode, degrees (5 by default).",
                 SettingRole::ElevationMask),
        RTK("ELGLO", "GLONASS elevation mask (RTK)", T::Integer, "deg", 0, 90, {}, "5",
            "GLONASS Elevation Mask for RTK mode, degrees (5 by default)."),
        RTK("ELSBAS", "SBAS elevation mask (RTK)", T::Integer, "deg", 0, 90, {}, "5",
            "SBAS Elevation Mask for RTK mode, degrees (5 by default)."),
        RTK("ELMASKA", "Elevation mask (autonomous)", T::Integer, "deg", 0, 90, {}, "5",
            "Elevation Mask for Autonomous mode, degrees (5 by default)."),
        RTK_ROLE("SNR", "SNR mask (RTK)", T::Integer, "dB-Hz", 0, 99, {}, "33",
                 "SNR Mask for RTK mode, dB-Hz (33 by default). Range 0-99 as GSV reports SNR.",
                 SettingRole::SnrMask),
        RTK("SNRMASKA", "SNR mask (autonomous)", T::Integer, "dB-Hz", 0, 99, {}, "12",
            "SNR Mask for Autonomous mode, dB-Hz (12 by default). Range 0-99 as GSV reports SNR."),
        RTK("RTCMAGE", "Differential age threshold", T::Integer, "s", 1, 999, {}, "45",
            "Differential age threshold (max age of RTCM data to use for RTK), seconds (45 by "
            "default). Range as PNVGBSS reports the data age (up to 999 s)."),
        RTK_ROLE("BASEID", "Base station ID", T::Integer, "", 0, 4095, {}, "2",
                 "Station ID for Base mode, 0 - 4095 (2 by default).", SettingRole::BaseStationId),
        RTK_ROLE("RTCMRATE", "RTCM raw data rate", T::Enum, "s", kNone, kNone, kRtcmRate, "1",
                 "Rate of RTCM messages with raw data (#1002 and #1010): 0 - same as PVT rate; 1 "
                 "(by "
                 "default), 2, 5, 10 - interval between RTCM messages, seconds.",
                 SettingRole::BaseRtcmInterval),
        RTK_ROLE("BASEXYZ", "Base antenna position (ECEF)", T::Coordinates, "m", kNone, kNone, {},
                 "", "Base Station Antenna Reference Point ECEF-X,Y,Z, m (three values x,y,z).",
                 SettingRole::BasePosition),
        RTK("BASEBLH", "Base antenna position (B,L,H)", T::Coordinates, "rad,rad,m", kNone, kNone,
            {}, "",
            "Base Station Antenna Reference Point. Two formats: B,L,H (radians for B and L, "
            "metres for H) or NMEA format (ddmm.mmmm,N,dddmm.mmmm,E,H)."),
        RTK_ROLE(
                "BASETH", "Base coordinates check threshold", T::Real, "m", 0, kNone, {}, "500",
                "BASE coordinates checking threshold, m (500 m by default). If the distance "
                "between "
                "BASE coordinates and the current 3D position in BASE mode exceeds it, RTCM output "
                "stops, the current position is given in NMEA and PNVGBSS shows the distance.",
                SettingRole::BaseThreshold),
        RTK_ROLE("BASENMEA", "NMEA coordinates in base mode", T::Enum, "", kNone, kNone, kBaseNmea,
                 "0",
                 "Type of coordinates used for NMEA output in BASE mode: 0 - BASE coordinates (by "
                 "default), 1 - current 3D coordinates.",
                 SettingRole::BaseNmeaPosition),
        RTK_ROLE("AVGTIME", "Position averaging time", T::Integer, "min", 1, kNone, {}, "30",
                 "Antenna position averaging time for Base mode, minutes (30 by default).",
                 SettingRole::BaseAveragingMinutes),
        RTK_ROLE("AVGMODE", "Position averaging input", T::Enum, "", kNone, kNone, kAvgMode, "0",
                 "Type of coordinates used for antenna position averaging: 0 (by default) - any "
                 "valid "
                 "coordinates, 1 - Fixed & Float, 2 - Fixed only.",
                 SettingRole::BaseAveragingInput),
        RTK("RAIM", "RAIM", T::Bool, "", kNone, kNone, kOnOff, "1",
            "RAIM mode: 0 - OFF, 1 - ON (by default)."),
        RTK("SFMODE", "Secondary filter mode", T::Enum, "", kNone, kNone, kSfMode, "0",
            "Secondary filter mode: 0 (by default) DISABLE - output follows the position type "
            "with possible jumps; 1 RETAIN - keep the relative offset; 2 TRANSITION - move "
            "slowly to the new position type at the Transfer Speed; 3 HYBRID - TRANSITION "
            "towards more accurate types, RETAIN towards less accurate ones."),
        RTK("SFTRS", "Secondary filter transfer speed", T::Real, "m/s", 0, kNone, {}, "0.05",
            "Transfer Speed for Secondary Filter, m/s (0.05 by default)."),
        RTK("DPFMODE", "Delta-phase filter", T::Bool, "", kNone, kNone, kOnOff, "0",
            "Delta-Phase Filter mode: 0 - OFF (by default), 1 - ON."),
        RTK("VRSMODE", "VRS mode", T::Bool, "", kNone, kNone, kOnOff, "0",
            "VRS mode: 0 - OFF (by default), 1 - ON."),
        RTK("ICBGLO", "GLONASS inter-channel bias", T::Real, "cycle", -1, 1, {}, "0",
            "GLONASS Inter-Channel Bias (0 by default): shift between phases of nearest GLONASS "
            "carriers in parts of phase cycle (hence -1..1)."),
        RTK("ICBMODE", "GLONASS ICB calibration", T::Enum, "", kNone, kNone, kIcbMode, "2",
            "GLONASS Inter-Channel Bias calibration mode: 0 - OFF (default for RTK FW 0028 and "
            "earlier), 1 - initial calibration (once, GPS as reference), 2 - real-time "
            "recalibration (default for RTK FW 0029)."),
        RTK("ICBTIME", "GLONASS ICB calibration interval", T::Integer, "s", 1, kNone, {}, "20",
            "GLONASS Inter-Channel Bias calibration interval (length of one step of "
            "calibration), seconds (20 by default)."),
        RTK("ICBMBGLO", "GLONASS ICB (moving base)", T::Real, "cycle", -1, 1, {}, "0",
            "GLONASS Inter-Channel Bias for moving-base mode (0 by default), in parts of phase "
            "cycle (hence -1..1)."),
        RTK("ICBMBMODE", "GLONASS ICB calibration (moving base)", T::Enum, "", kNone, kNone,
            kIcbMode, "0",
            "GLONASS Inter-Channel Bias calibration mode for moving-base mode: 0 - OFF (by "
            "default), 1 - initial calibration, 2 - real-time recalibration."),
        RTK("ICBMBTIME", "GLONASS ICB calibration interval (moving base)", T::Integer, "s", 1,
            kNone, {}, "20",
            "GLONASS Inter-Channel Bias calibration interval for moving-base mode, seconds (20 by "
            "default)."),
        RTK("BASELINE", "ANT1-ANT2 base-line length", T::Real, "m", 0, kNone, {}, "0.0",
            "ANT1-ANT2 base-line length for Heading mode, metres (0.0 by default: base-line "
            "constraint disabled)."),
        RTK("INITGPSWEEK", "Initial GPS week", T::Integer, "", 0, 9999, {}, "",
            "Initial GPS Week Number for counting time in Cold Start mode (default value depends "
            "on RTK FW release date)."),

        // ---- 4.2 PNVGNME ----
        NME("time_decimals", "Time decimals", T::Integer, 0, 6, {}, "2",
            "Number of digits in fractional part of time output, 0 to 6 (2 by default). PNVGNME "
            "sets time and position decimals together.",
            "[,<talker mode>]"),
        NME("position_decimals", "Position decimals", T::Integer, 0, 9, {}, "7",
            "Number of digits in fractional part of position output, 0 to 9 (7 by default).",
            "[,<talker mode>]"),
        NME("talker_mode", "Talker ID compatibility", T::Enum, kNone, kNone, kTalker, "0",
            "0 - Talker ID for GGA and RMC always GP (by default); 1 - compatibility mode off, "
            "talker ID as specified (GN for combined solutions). Optional field.",
            ",<talker mode>"),

        // ---- 4.4 PNVGRZA per port ----
        // The simulated and usual host is on COM1: its speed is the link's.
        PORT("1", "COM1", SettingRole::PortSpeed),
        PORT("2", "COM2", SettingRole::PortSpeedOf),
        PORT("3", "USB", SettingRole::PortSpeedOf),

        // ---- 4.5 PNVGRZB output lists per port ----
        OUTPUT("1", "COM1"),
        OUTPUT("2", "COM2"),
        OUTPUT("3", "USB"),

        // ---- 4.9 PNVGPPS (empty fields stay unchanged; all empty reads the settings back) ----
        PPS("type", "Time pulse type", T::Enum, "", kNone, kNone, kPpsType, "P",
            "P (by default) - software-synchronised time pulse; A - hardware-synchronised "
            "(aligned to internal timescale).",
            "$PNVGPPS,<type>,...", "$PNVGPPS,<type>,,,,,,"),
        PPS("mode", "Software time pulse", T::Enum, "", kNone, kNone, kPpsMode, "S",
            "I - interval time pulse at PVT update rate; S (by default) - 1PPS, one pulse per "
            "second.",
            "field 2", "$PNVGPPS,,<mode>,,,,,"),
        PPS("reference", "1PPS reference", T::Enum, "", kNone, kNone, kPpsRef, "U",
            "1PPS time pulse reference: U - UTC (by default), S - UTC(SU), G - GLONASS time, N - "
            "GPS time. Applies to 1PPS only.",
            "field 3", "$PNVGPPS,,,<reference>,,,,"),
        PPS("adjust", "Timescale adjustment", T::Bool, "", kNone, kNone, kOnOff, "1",
            "Internal receiver timescale adjustment: 1 - On (by default), adjusted once the "
            "offset to UTC exceeds 1 ms; 0 - Off (not recommended).",
            "field 4", "$PNVGPPS,,,,<adjust>,,,"),
        PPS("duration", "Pulse duration", T::Integer, "us", 1, 1000, {}, "1000",
            "Software-defined time pulse duration in microseconds, 1 to 1000 (1000 by default).",
            "field 5", "$PNVGPPS,,,,,<duration>,,"),
        PPS("validity", "PPS validity control", T::Enum, "", kNone, kNone, kPpsValid, "D",
            "Output PPS only with a valid navigation solution and UTC parameters: E - enabled, "
            "D - disabled (by default).",
            "field 6", "$PNVGPPS,,,,,,<validity>,"),
        PPS("cable_delay", "Antenna cable delay", T::Integer, "ns", 0, 9999, {}, "0",
            "Delay in antenna cable in nanoseconds (0 by default). Range from the field's four "
            "digits (xxxx).",
            "field 7", "$PNVGPPS,,,,,,,<delay>"),

        // ---- 4.15 PNVGIDL ----
        {.key = "idl.mode",
         .label = "Base station filter",
         .group = "Base stations",
         .type = T::Enum,
         .options = kIdlMode,
         .defaultValue = "0",
         .help = "0 - the receiver may use any base station (by default); 1 - only base "
                 "stations from the list are allowed.",
         .access = SettingAccess::WriteOnly,
         .readBack = "none documented ($PNVGIDL,MODE,<x> is echoed when set)",
         .write = "$PNVGIDL,MODE,<mode>",
         .command = &kIdlModeCommand},
        {.key = "idl.stations",
         .label = "Known base stations",
         .group = "Base stations",
         .type = T::List,
         .help = "Known base stations (at most 32) as ID:ICB items separated by ';' "
                 "(\"3:0.072;43:0\"); ID 0-4095, ICB = GLONASS inter-channel bias in parts of "
                 "phase cycle. Written as CLEAR then one ADD per station.",
         .readBack = "$PNVGIDL,SHOW -> $PNVGIDL,<count>,<index>,<id>,<icb> per station",
         .write = "$PNVGIDL,CLEAR then $PNVGIDL,ADD,<id>,<icb> per station",
         .command = &kStationsCommand},
};

#undef RTK
#undef PORT
#undef OUTPUT
#undef PPS
#undef NME

constexpr std::string_view kPorts[] = {"current", "COM1", "COM2", "USB"};

} // namespace

std::span<const SettingDef> settingsSchema() {
    return kSchema;
}

std::string_view portName(int port) {
    return port >= 0 && port <= 3 ? kPorts[port] : std::string_view{};
}

int portNumber(std::string_view name) {
    for (int i = 1; i <= 3; ++i)
        if (kPorts[i] == name) return i;
    return -1;
}

} // namespace gnss::nvs
