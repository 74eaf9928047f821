// The Nemerix settings schema: every configurable parameter, as data. The forms, `gnss-cli
// schema nemerix`, `gnss-cli encode nemerix`, profiles and the simulator all read this table;
// nemerix_settings.cpp turns values into commands and PNMRX603 reports back into values.
//
// Read-back: PNMRX603 reports most fix masks, the datum, the time zone, the channel count and
// (inferred) the NMEA rates. The serial port, output sequence, Nemerix message modes,
// navigation modes, VDOP/altitude limits and power mode are not reported (or only in words whose
// layout the spec does not give): those are write-only.
#include "core/number_options.h"
#include "nemerix/nemerix_actions.h"
#include "nemerix/nemerix_dialect_parts.h"

namespace gnss::nemerix {

namespace {

using T = SettingType;
using A = SettingAccess;

constexpr SettingOption kProtocols[] = {{"0", "NMEA"}, {"1", "Nemerix binary (under development)"}};
constexpr SettingOption kParities[] = {{"0", "None"}, {"1", "Odd"}, {"2", "Even"}};
constexpr SettingOption kNmrxModes[] = {{"0", "Disabled"},
                                        {"1", "Send now"},
                                        {"2", "Send on change"},
                                        {"3", "Send now and on change"}};
constexpr SettingOption kCorrection[] = {{"0", "No geoid correction"},
                                         {"1", "EGM96 geoid correction (datum 216 only)"}};
constexpr SettingOption kNavMode1[] = {
        {"1", "Auto (hold altitude)"}, {"2", "2D"}, {"4", "3D (compute altitude)"}};
constexpr SettingOption kNavMode2[] = {{"0", "Auto"}, {"1", "Static"}};
constexpr SettingOption kPowerModes[] = {{"0", "Fully active"}, {"1", "LDCM1 (low duty cycle)"}};

constexpr const char *kRateHelp =
        "Output interval in seconds (0 = not output). Read back from PNMRX603 message 0, message "
        "delays, assumed to be in the order GGA GLL GSA GSV RMC VTG ZDA.";
constexpr const char *kRateRead = "PNMRX603 message 0, message delay (order inferred)";

// What the rows of one command share; each row adds its own names and texts (rowOf).
constexpr SettingDef kRateRows{.group = "NMEA output", // PNMRX103: one message's interval
                               .type = T::Integer,
                               .unit = "s",
                               .min = 0,
                               .max = 9,
                               .help = kRateHelp,
                               .readBack = kRateRead,
                               .command = &kRatesCommand};
constexpr SettingDef kNmrxRows{.group = "Nemerix messages", // PNMRX107: when one is sent
                               .type = T::Enum,
                               .options = kNmrxModes,
                               .access = A::WriteOnly,
                               .command = &kNemerixRatesCommand};
constexpr SettingDef kDatumOffsetRows{.group = "Datum", // PNMRX106: the user datum's offset
                                      .type = T::Integer,
                                      .unit = "m",
                                      .min = -9999,
                                      .max = 9999,
                                      .write = "$PNMRX106,<c>,500,<dx>,<dy>,<dz>,<iflat>,<majora>",
                                      .command = &kDatumCommand};
constexpr SettingDef kDopMaskRows{.group = "Fix masks", // PNMRX110 masks 1-3, sent x10
                                  .type = T::Real,
                                  .min = 0,
                                  .max = 10,
                                  .command = &kFixMaskCommand};

// A row of `family` under its own key and label; a text left empty keeps the family's.
struct OwnTexts {
    std::string_view key, label, write, defaultValue, help, readBack;
};
constexpr SettingDef rowOf(SettingDef family, const OwnTexts &own) {
    family.key = own.key;
    family.label = own.label;
    if (!own.write.empty()) family.write = own.write;
    if (!own.defaultValue.empty()) family.defaultValue = own.defaultValue;
    if (!own.help.empty()) family.help = own.help;
    if (!own.readBack.empty()) family.readBack = own.readBack;
    return family;
}

constexpr SettingDef kSchema[] = {
        // ---- Serial port (PNMRX100) -------------------------------------------------------
        {"serial.protocol",
         "Protocol",
         "Serial port",
         T::Enum,
         "",
         {},
         {},
         kProtocols,
         "0",
         "Port protocol. Sent with the baud rate (serial.baud is required) and parity.",
         A::WriteOnly,
         "",
         "$PNMRX100,<protocol>,<baud>,<parity>",
         &kSerialCommand},
        {"serial.baud",
         "Baud rate",
         "Serial port",
         T::Enum,
         "bit/s",
         {},
         {},
         kNumberOptions<kSupportedBauds>,
         "9600",
         "Serial speed; the port switches right after the command. The UART word of PNMRX603 "
         "message 0 has no documented layout, so the speed cannot be read back.",
         A::WriteOnly,
         "",
         "$PNMRX100,<protocol>,<baud>,<parity>",
         &kSerialCommand,
         SettingRole::PortSpeed},
        {"serial.parity",
         "Parity",
         "Serial port",
         T::Enum,
         "",
         {},
         {},
         kParities,
         "0",
         "Parity, sent with the baud rate (serial.baud is required).",
         A::WriteOnly,
         "",
         "$PNMRX100,<protocol>,<baud>,<parity>",
         &kSerialCommand},

        // ---- NMEA output (PNMRX103, PNMRX108) --------------------------------------------
        rowOf(kRateRows, {"rate.GGA", "GGA interval", "$PNMRX103,GGA,<s>", "1"}),
        rowOf(kRateRows, {"rate.GLL", "GLL interval", "$PNMRX103,GLL,<s>", "0"}),
        rowOf(kRateRows, {"rate.GSA", "GSA interval", "$PNMRX103,GSA,<s>", "3"}),
        rowOf(kRateRows, {"rate.GSV", "GSV interval", "$PNMRX103,GSV,<s>", "3"}),
        rowOf(kRateRows, {"rate.RMC", "RMC interval", "$PNMRX103,RMC,<s>", "1"}),
        rowOf(kRateRows, {"rate.VTG", "VTG interval", "$PNMRX103,VTG,<s>", "1"}),
        rowOf(kRateRows, {"rate.ZDA", "ZDA interval", "$PNMRX103,ZDA,<s>", "0"}),
        {"output.sequence",
         "Output sequence",
         "NMEA output",
         T::List,
         "",
         {},
         {},
         {},
         "GGA;GSA;GSV;RMC;VTG",
         "Messages to output, in this order, separated by ';' (GGA GLL GSA GSV RMC VTG ZDA); "
         "the others are disabled, the listed ones output every second until rate.* changes "
         "them. The sequence in PNMRX603 message 0 has no documented layout.",
         A::WriteOnly,
         "",
         "$PNMRX108,<id>,<id>,...",
         &kSequenceCommand},

        // ---- Nemerix messages (PNMRX107) -------------------------------------------------
        rowOf(kNmrxRows, {"nmrx.300", "Almanac (PNMRX300)", "$PNMRX107,300,<mode>", "",
                          "When the receiver sends its almanac."}),
        rowOf(kNmrxRows, {"nmrx.301", "Ephemeris (PNMRX301)", "$PNMRX107,301,<mode>", "",
                          "When the receiver sends ephemerides."}),
        rowOf(kNmrxRows, {"nmrx.302", "Ionosphere (PNMRX302)", "$PNMRX107,302,<mode>", "",
                          "When the receiver sends ionospheric corrections."}),
        rowOf(kNmrxRows, {"nmrx.303", "UTC (PNMRX303)", "$PNMRX107,303,<mode>", "",
                          "When the receiver sends GPS-UTC parameters."}),
        rowOf(kNmrxRows, {"nmrx.304", "Health (PNMRX304)", "$PNMRX107,304,<mode>", "",
                          "When the receiver sends constellation health."}),

        // ---- Datum (PNMRX106) ------------------------------------------------------------
        {"datum.correction",
         "EGM96 correction",
         "Datum",
         T::Enum,
         "",
         {},
         {},
         kCorrection,
         "0",
         "Apply the EGM96 geoid correction (only meaningful with datum 216).",
         A::ReadWrite,
         "PNMRX603 message 4, correction mode",
         "$PNMRX106,<correction>,<datum>,...",
         &kDatumCommand},
        {"datum.mapDatum",
         "Map datum",
         "Datum",
         T::Integer,
         "",
         0,
         500,
         {},
         "216",
         "0-218: internal table; 500: user defined (needs dx, dy, dz, inverse flattening and "
         "semi-major axis).",
         A::ReadWrite,
         "PNMRX603 message 4, map datum",
         "$PNMRX106,<correction>,<datum>,...",
         &kDatumCommand},
        rowOf(kDatumOffsetRows,
              {"datum.dx", "Dx", "", "", "X offset of the user datum.", "PNMRX603 message 4, Dx"}),
        rowOf(kDatumOffsetRows,
              {"datum.dy", "Dy", "", "", "Y offset of the user datum.", "PNMRX603 message 4, Dy"}),
        rowOf(kDatumOffsetRows,
              {"datum.dz", "Dz", "", "", "Z offset of the user datum.", "PNMRX603 message 4, Dz"}),
        {"datum.inverseFlattening",
         "Inverse flattening",
         "Datum",
         T::Real,
         "",
         296,
         302,
         {},
         "",
         "1/f of the user ellipsoid (sent as (1/f - 290) x 1e6).",
         A::ReadWrite,
         "PNMRX603 message 4, inverse flatness",
         "$PNMRX106,<c>,500,...,<iflat>,<majora>",
         &kDatumCommand},
        {"datum.semiMajorAxis",
         "Semi-major axis",
         "Datum",
         T::Real,
         "m",
         6376000,
         6379000,
         {},
         "",
         "Semi-major axis of the user ellipsoid (sent as (a - 6370000) x 1000).",
         A::ReadWrite,
         "PNMRX603 message 4, major axis",
         "$PNMRX106,<c>,500,...,<majora>",
         &kDatumCommand},

        // ---- Fix masks (PNMRX110) --------------------------------------------------------
        {"fix.timeZone",
         "Local time zone",
         "Fix masks",
         T::Text,
         "h:m",
         {},
         {},
         {},
         "0:0",
         "Local time zone as hours:minutes, hours -13..13 (mask 0).",
         A::ReadWrite,
         "PNMRX603 message 1, time offset",
         "$PNMRX110,0,<h:m>",
         &kFixMaskCommand},
        rowOf(kDopMaskRows, {"fix.maxPdop", "Maximum PDOP", "$PNMRX110,1,<x10>", "",
                             "Mask 1 (sent x10).", "PNMRX603 message 2, MaxPDOP"}),
        rowOf(kDopMaskRows, {"fix.maxHdop", "Maximum HDOP", "$PNMRX110,2,<x10>", "",
                             "Mask 2 (sent x10).", "PNMRX603 message 2, MaxHDOP"}),
        {"fix.maxVdop",
         "Maximum VDOP",
         "Fix masks",
         T::Real,
         "",
         0,
         10,
         {},
         "",
         "Mask 3 (sent x10). Not in the settings report.",
         A::WriteOnly,
         "",
         "$PNMRX110,3,<x10>",
         &kFixMaskCommand},
        {"fix.minSnr",
         "Minimum SNR",
         "Fix masks",
         T::Integer,
         "dB-Hz",
         20,
         45,
         {},
         "",
         "Mask 4.",
         A::ReadWrite,
         "PNMRX603 message 2, Min CNO",
         "$PNMRX110,4,<snr>",
         &kFixMaskCommand,
         SettingRole::SnrMask},
        {"fix.minElevation",
         "Minimum elevation",
         "Fix masks",
         T::Integer,
         "deg",
         0,
         90,
         {},
         "",
         "Mask 5.",
         A::ReadWrite,
         "PNMRX603 message 2, Min Elevation",
         "$PNMRX110,5,<deg>",
         &kFixMaskCommand,
         SettingRole::ElevationMask},
        {"fix.noiseFloor",
         "Noise floor",
         "Fix masks",
         T::Integer,
         "",
         400,
         1000,
         {},
         "",
         "Mask 6.",
         A::ReadWrite,
         "PNMRX603 message 3, Noise floor",
         "$PNMRX110,6,<n>",
         &kFixMaskCommand},
        {"fix.altitude2d",
         "2D mode altitude",
         "Fix masks",
         T::Integer,
         "m",
         0,
         999999,
         {},
         "",
         "Mask 8: altitude above MSL held in 2D mode. Read back from the report's 'Default "
         "altitude' (inferred to be the same value).",
         A::ReadWrite,
         "PNMRX603 message 3, Default altitude",
         "$PNMRX110,8,<m>",
         &kFixMaskCommand},
        {"fix.maxAltitude",
         "Maximum altitude",
         "Fix masks",
         T::Integer,
         "m",
         0,
         999999,
         {},
         "",
         "Mask 10. Not in the settings report.",
         A::WriteOnly,
         "",
         "$PNMRX110,10,<m>",
         &kFixMaskCommand},

        // ---- Navigation mode (PNMRX110 masks 7 and 9, PNMRX101 channel count) -----------
        {"nav.mode",
         "Navigation mode",
         "Navigation mode",
         T::Enum,
         "",
         {},
         {},
         kNavMode1,
         "",
         "Mask 7. Not in the settings report (the report's Kalman mode has no documented "
         "meaning).",
         A::WriteOnly,
         "",
         "$PNMRX110,7,<mode>",
         &kFixMaskCommand},
        {"nav.dynamics",
         "Static navigation",
         "Navigation mode",
         T::Enum,
         "",
         {},
         {},
         kNavMode2,
         "",
         "Mask 9.",
         A::WriteOnly,
         "",
         "$PNMRX110,9,<0|1>",
         &kFixMaskCommand},
        {"nav.channels",
         "Channel count",
         "Navigation mode",
         T::Integer,
         "",
         12,
         16,
         {},
         "",
         "Maximum number of tracking modules used.",
         A::ReadWrite,
         "PNMRX603 message 2, Max TM",
         "$PNMRX101,,,,,,,<n>,",
         &kNavInitCommand},

        // ---- Power mode (PNMRX112) -------------------------------------------------------
        {"power.mode",
         "Operating mode",
         "Power mode",
         T::Enum,
         "",
         {},
         {},
         kPowerModes,
         "0",
         "Low power starts only once the receiver has a complete almanac and a fix.",
         A::WriteOnly,
         "",
         "$PNMRX112,<mode>,<off>",
         &kPowerCommand},
        {"power.offPeriod",
         "RF off period",
         "Power mode",
         T::Integer,
         "s",
         5,
         10,
         {},
         "",
         "RF off time between two fixes in LDCM1 (implies power.mode=1).",
         A::WriteOnly,
         "",
         "$PNMRX112,1,<s>",
         &kPowerCommand},
};

} // namespace

std::span<const SettingDef> settingsSchema() {
    return kSchema;
}

} // namespace gnss::nemerix
