// GeoS-5 settings schema (section 4 commands; read back from RQUERY 3.11 / NQUERY 3.12).
// The spec gives no factory defaults, so defaultValue stays empty.
#include "geostar/geostar_schema.h"

#include "core/field_parse.h"
#include "core/number_options.h"
#include "core/setting_command.h"
#include "geostar/geostar_actions.h"
#include "geostar/geostar_commands.h"

#include <algorithm>

namespace gnss::geostar {
namespace {

using A = SettingAccess;
using T = SettingType;

constexpr SettingOption kStop[] = {{"1", "1 stop bit"}, {"2", "2 stop bits"}};
constexpr SettingOption kNmea[] = {{"2", "NMEA v2.x"}, {"4", "NMEA v4.10"}};
constexpr SettingOption kRate[] = {{"1", "1 Hz"}, {"2", "2 Hz"}, {"5", "5 Hz"}, {"10", "10 Hz"}};
constexpr SettingOption kDatum[] = {
        {"W84", "WGS-84"},
        {"P90", "PZ-90.11"},
        {"999", "user-defined (reported by RQUERY; cannot be selected by an NMEA command)"}};
constexpr SettingOption kGnss[] = {
        {"GPS", "GPS only"}, {"GLN", "GLONASS only"}, {"MIX", "GLONASS+GPS+Galileo"}};
constexpr SettingOption kStart[] = {
        {"cold", "cold start"}, {"warm", "warm start"}, {"hot", "hot start"}};
constexpr SettingOption kSave[] = {{"1", "save almanacs to flash"}};
constexpr SettingOption kSwprot[] = {{"binary", "switch the port to the binary protocol"}};

std::string lower(std::string_view s) {
    std::string r(s);
    for (char &c : r)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return r;
}

// What the user typed → the value of the command table ("ON" → "1", "05" → "5").
std::string normalise(const SettingDef &d, std::string_view value) {
    if (d.type == T::Bool) {
        const std::string l = lower(value);
        if (l == "on" || l == "true" || l == "yes") return "1";
        if (l == "off" || l == "false" || l == "no") return "0";
    }
    if (d.type == T::Integer) {
        std::int64_t v;
        if (parseInt(value, v)) return std::to_string(v);
    }
    return std::string(value);
}

// ---- The commands the rows name: each value is one command text of the table (4.x) ----------

Refusal validateByTable(const SettingDef &d, std::string_view value) {
    const std::string v = normalise(d, value);
    if (Refusal e = validateSetting(d, v); !e.empty()) return e;
    if (!findCommandFor(d.key, v))
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is reported by the receiver but "
                                                    "cannot be set with an NMEA command"),
                       {std::string(d.key), v});
    return {};
}

const SettingDef &rowOf(std::string_view key);

EncodeResult writeByTable(std::span<const KeyValue> values) {
    EncodeResult r;
    for (const auto &kv : values)
        r.sentences.push_back(
                encodeCommand(*findCommandFor(kv.key, normalise(rowOf(kv.key), kv.value))));
    return r;
}

EncodeResult query(std::string_view text) {
    EncodeResult r;
    r.sentences.push_back(encodeCommand(*findCommand(text)));
    return r;
}
EncodeResult readNquery(std::span<const std::string>) {
    return query("NQUERY");
}
EncodeResult readRquery(std::span<const std::string>) {
    return query("RQUERY");
}

// Every command of the rows validates and writes by the command table; what differs is how it is
// confirmed (set commands are answered with nothing: the query that reports them is the
// confirmation) and what changes the link: a restart, then the port's framing, then leaving NMEA.
constexpr SettingCommand byTable(SettingCommand c) {
    c.validate = validateByTable;
    c.write = writeByTable;
    return c;
}
constexpr SettingCommand kOutputCommand =
        byTable({.name = "GPSGG (output, NQUERY)", .confirmedByRead = true, .read = readNquery});
constexpr SettingCommand kConfigCommand = byTable(
        {.name = "GPSGG (configuration, RQUERY)", .confirmedByRead = true, .read = readRquery});
constexpr SettingCommand kUnreportedCommand = byTable({.name = "GPSGG (not reported)"});
constexpr SettingCommand kRestartCommand =
        byTable({.name = "GPSGG,xSTART", .changesLink = true, .order = 0});
constexpr SettingCommand kPortCommand =
        byTable({.name = "GPSGG,BDR/STOP", .changesLink = true, .order = 1});
constexpr SettingCommand kProtocolCommand =
        byTable({.name = "GPSGG,SWPROT", .changesLink = true, .order = 2});

#define GEOSTAR_OUTPUT(MSG, LABEL, HELP, FIELD)                                                    \
    SettingDef {                                                                                   \
        .key = "output." MSG, .label = LABEL, .group = "Output messages", .type = T::Bool,         \
        .help = HELP, .access = A::ReadWrite,                                                      \
        .readBack = "NQUERY reply, field " FIELD " (" MSG " rate code; 0 = off, 1/2/3/R = on)",    \
        .write = "$GPSGG," MSG " ON / $GPSGG," MSG "OFF", .command = &kOutputCommand               \
    }

constexpr SettingDef kSchema[] = {
        GEOSTAR_OUTPUT("GGA", "GGA/GNS output", "GGA, and GNS in v4.10 (4.10)", "4"),
        GEOSTAR_OUTPUT("GLL", "GLL output", "Geographic position (4.11)", "5"),
        GEOSTAR_OUTPUT("GSA", "GSA output", "DOP and active satellites (4.12)", "6"),
        GEOSTAR_OUTPUT("GSV", "GSV output", "Satellites in view (4.13)", "7"),
        GEOSTAR_OUTPUT("RMC", "RMC output", "Recommended minimum data (4.14)", "8"),
        GEOSTAR_OUTPUT("VTG", "VTG output", "Course and speed (4.15)", "9"),
        GEOSTAR_OUTPUT("ZDA", "ZDA output", "Time and date (4.16)", "11"),
        GEOSTAR_OUTPUT("DTM", "DTM output", "Datum (4.17)", "12"),
        GEOSTAR_OUTPUT("RLM", "RLM output", "Galileo return link message (4.18)", "13"),
        {.key = "output.NMEAV",
         .label = "NMEA version",
         .group = "Output messages",
         .type = T::Enum,
         .options = kNmea,
         .help = "NMEA 0183 standard of the output: v2.x or v4.10 (4.19)",
         .readBack = "NQUERY reply, field 3 (2 = v2.x, 4 = v4.10)",
         .write = "$GPSGG,NMEAV2 / $GPSGG,NMEAV4",
         .command = &kOutputCommand},
        {.key = "output.RATE",
         .label = "Output rate",
         .group = "Output messages",
         .type = T::Enum,
         .unit = "Hz",
         .options = kRate,
         .help = "Navigation output rate (4.20)",
         .readBack = "NQUERY reply, field 2 (0 = 10 Hz, 1 = 5 Hz, 2 = 2 Hz, 3 = 1 Hz); also "
                     "RQUERY configuration register 1 bits 19:18",
         .write = "$GPSGG,RATE01 / RATE02 / RATE05 / RATE10",
         .command = &kOutputCommand,
         .role = SettingRole::OutputRate},
        {.key = "power.PSM",
         .label = "Power saving",
         .group = "Power",
         .type = T::Bool,
         .help = "Power saving modes on/off; in FIX-BY-REQUEST sleep, PSM ON wakes the receiver "
                 "(4.21). Read back inferred from table 8 bit 24 (power saving modes enabled).",
         .readBack = "RQUERY reply, configuration register 1 bit 24",
         .write = "$GPSGG,PSM ON / $GPSGG,PSMOFF",
         .command = &kConfigCommand},
        {.key = "nav.ELEV",
         .label = "Elevation mask",
         .group = "Navigation",
         .type = T::Integer,
         .unit = "deg",
         .min = 5,
         .max = 15,
         .help = "Satellites below the mask are not used in the solution (4.22)",
         .access = A::WriteOnly,
         .readBack = "not reported by RQUERY or NQUERY",
         .write = "$GPSGG,ELEVnn (nn = 05..15)",
         .command = &kUnreportedCommand,
         .role = SettingRole::ElevationMask},
        {.key = "nav.DAT",
         .label = "Datum",
         .group = "Navigation",
         .type = T::Enum,
         .options = kDatum,
         .help = "Coordinate system of the navigation output (4.23)",
         .readBack = "RQUERY reply, configuration register 2 bits 15:14 (0 = WGS-84, "
                     "1 = PZ-90.11, 2 = user-defined)",
         .write = "$GPSGG,DATW84 / $GPSGG,DATP90",
         .command = &kConfigCommand},
        {.key = "nav.NVS",
         .label = "Constellations",
         .group = "Navigation",
         .type = T::Enum,
         .options = kGnss,
         .help = "GNSS used: GPS only, GLONASS only or GLONASS+GPS+Galileo (4.24)",
         .readBack = "RQUERY reply, configuration register 1 bits 2:0 (Galileo, GPS, GLONASS in "
                     "use)",
         .write = "$GPSGG,NVSGPS / NVSGLN / NVSMIX",
         .command = &kConfigCommand},
        {.key = "port.BDR",
         .label = "Baud rate",
         .group = "Port",
         .type = T::Enum,
         .unit = "bit/s",
         .options = kNumberOptions<kSupportedBauds>, // BDR004 ... BDR921
         .help = "Serial port speed; takes effect after the command (4.8)",
         .access = A::WriteOnly,
         .readBack = "not reported (NQUERY gives the port number only)",
         .write = "$GPSGG,BDR004 / 009 / 019 / 038 / 057 / 115 / 230 / 460 / 921",
         .command = &kPortCommand,
         .role = SettingRole::PortSpeed},
        {.key = "port.STOP",
         .label = "Stop bits",
         .group = "Port",
         .type = T::Enum,
         .options = kStop,
         .help = "Serial port stop bits (4.9)",
         .access = A::WriteOnly,
         .readBack = "not reported by RQUERY or NQUERY",
         .write = "$GPSGG,STOP01 / $GPSGG,STOP02",
         .command = &kPortCommand},
        {.key = "action.START",
         .label = "Restart",
         .group = "Actions",
         .type = T::Enum,
         .options = kStart,
         .help = "Cold, warm or hot start (4.3-4.5)",
         .access = A::WriteOnly,
         .readBack = "an action: nothing to read back",
         .write = "$GPSGG,CSTART / WSTART / HSTART",
         .command = &kRestartCommand},
        {.key = "action.SAVEFL",
         .label = "Save almanacs",
         .group = "Actions",
         .type = T::Enum,
         .options = kSave,
         .help = "Save almanacs to flash (4.2)",
         .access = A::WriteOnly,
         .readBack = "an action: nothing to read back (RQUERY status bit 30 shows a write in "
                     "progress)",
         .write = "$GPSGG,SAVEFL",
         .command = &kUnreportedCommand},
        {.key = "action.SWPROT",
         .label = "Binary protocol",
         .group = "Actions",
         .type = T::Enum,
         .options = kSwprot,
         .help = "Switch the port from NMEA to the binary protocol (4.1)",
         .access = A::WriteOnly,
         .readBack = "an action: nothing to read back",
         .write = "$GPSGG,SWPROT",
         .command = &kProtocolCommand},
};

#undef GEOSTAR_OUTPUT

const SettingDef &rowOf(std::string_view key) {
    return *findSetting(kSchema, key);
}

} // namespace

std::span<const SettingDef> settingsSchema() {
    return kSchema;
}

} // namespace gnss::geostar
