// Section 4 of the GeoS-5 NMEA protocol v4.0: every input command, as data, and its encoders.
#include "geostar/geostar_commands.h"

#include "core/sentence_builder.h"
#include "core/settings_plan.h"
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_schema.h"

namespace gnss::geostar {
namespace {

using E = CommandEffect;

// clang-format off
constexpr CommandDef kCommands[] = {
    {"SWPROT", "4.1", "action.SWPROT", "binary", "Switch the port to the binary protocol", E::ChangesProtocol, "", "75"},
    {"SAVEFL", "4.2", "action.SAVEFL", "1", "Save almanacs to flash", E::None, "", "63"},
    {"CSTART", "4.3", "action.START", "cold", "Cold start", E::ResetsReceiver, "", "6B"},
    {"WSTART", "4.4", "action.START", "warm", "Warm start", E::ResetsReceiver, "", "7F"},
    {"HSTART", "4.5", "action.START", "hot", "Hot start", E::ResetsReceiver, "", "60"},
    {"RQUERY", "4.6", "", "", "Query firmware version, telemetry and configuration", E::None, "", "70"},
    {"NQUERY", "4.7", "", "", "Query the NMEA output list and rates", E::None, "", "6C"},
    {"BDR004", "4.8", "port.BDR", "4800", "Serial port speed 4800 bit/s", E::ChangesBaud, "", "08"},
    {"BDR009", "4.8", "port.BDR", "9600", "Serial port speed 9600 bit/s", E::ChangesBaud, "", "05"},
    {"BDR019", "4.8", "port.BDR", "19200", "Serial port speed 19200 bit/s", E::ChangesBaud, "", "04"},
    {"BDR038", "4.8", "port.BDR", "38400", "Serial port speed 38400 bit/s", E::ChangesBaud, "", "07"},
    {"BDR057", "4.8", "port.BDR", "57600", "Serial port speed 57600 bit/s", E::ChangesBaud, "", "0E"},
    {"BDR115", "4.8", "port.BDR", "115200", "Serial port speed 115200 bit/s", E::ChangesBaud, "", "09"},
    {"BDR230", "4.8", "port.BDR", "230400", "Serial port speed 230400 bit/s", E::ChangesBaud, "", "0D"},
    {"BDR460", "4.8", "port.BDR", "460800", "Serial port speed 460800 bit/s", E::ChangesBaud, "", "0E"},
    {"BDR921", "4.8", "port.BDR", "921600", "Serial port speed 921600 bit/s", E::ChangesBaud, "", "06"},
    {"STOP01", "4.9", "port.STOP", "1", "Serial port: 1 stop bit", E::ChangesBaud, "", "71"},
    {"STOP02", "4.9", "port.STOP", "2", "Serial port: 2 stop bits", E::ChangesBaud, "", "72"},
    {"GGA ON", "4.10", "output.GGA", "1", "GGA/GNS output on", E::ChangesOutput, "NQUERY", "08"},
    {"GGAOFF", "4.10", "output.GGA", "0", "GGA/GNS output off", E::ChangesOutput, "NQUERY", "66"},
    {"GLL ON", "4.11", "output.GLL", "1", "GLL output on", E::ChangesOutput, "NQUERY", "0E"},
    {"GLLOFF", "4.11", "output.GLL", "0", "GLL output off", E::ChangesOutput, "NQUERY", "60"},
    {"GSA ON", "4.12", "output.GSA", "1", "GSA output on", E::ChangesOutput, "NQUERY", "1C"},
    {"GSAOFF", "4.12", "output.GSA", "0", "GSA output off", E::ChangesOutput, "NQUERY", "72"},
    {"GSV ON", "4.13", "output.GSV", "1", "GSV output on", E::ChangesOutput, "NQUERY", "0B"},
    {"GSVOFF", "4.13", "output.GSV", "0", "GSV output off", E::ChangesOutput, "NQUERY", "65"},
    {"RMC ON", "4.14", "output.RMC", "1", "RMC output on", E::ChangesOutput, "NQUERY", "15"},
    {"RMCOFF", "4.14", "output.RMC", "0", "RMC output off", E::ChangesOutput, "NQUERY", "7B"},
    {"VTG ON", "4.15", "output.VTG", "1", "VTG output on", E::ChangesOutput, "NQUERY", "0C"},
    {"VTGOFF", "4.15", "output.VTG", "0", "VTG output off", E::ChangesOutput, "NQUERY", "62"},
    {"ZDA ON", "4.16", "output.ZDA", "1", "ZDA output on", E::ChangesOutput, "NQUERY", "16"},
    {"ZDAOFF", "4.16", "output.ZDA", "0", "ZDA output off", E::ChangesOutput, "NQUERY", "78"},
    {"DTM ON", "4.17", "output.DTM", "1", "DTM output on", E::ChangesOutput, "NQUERY", "14"},
    {"DTMOFF", "4.17", "output.DTM", "0", "DTM output off", E::ChangesOutput, "NQUERY", "7A"},
    {"RLM ON", "4.18", "output.RLM", "1", "RLM output on", E::ChangesOutput, "NQUERY", "1A"},
    {"RLMOFF", "4.18", "output.RLM", "0", "RLM output off", E::ChangesOutput, "NQUERY", "74"},
    {"NMEAV2", "4.19", "output.NMEAV", "2", "NMEA standard v2.x", E::ChangesOutput, "NQUERY", "0B"},
    {"NMEAV4", "4.19", "output.NMEAV", "4", "NMEA standard v4.10", E::ChangesOutput, "NQUERY", "0D"},
    {"RATE01", "4.20", "output.RATE", "1", "Output rate 1 Hz", E::ChangesOutput, "NQUERY", "6B"},
    {"RATE02", "4.20", "output.RATE", "2", "Output rate 2 Hz", E::ChangesOutput, "NQUERY", "68"},
    {"RATE05", "4.20", "output.RATE", "5", "Output rate 5 Hz", E::ChangesOutput, "NQUERY", "6F"},
    {"RATE10", "4.20", "output.RATE", "10", "Output rate 10 Hz", E::ChangesOutput, "NQUERY", "6B"},
    {"PSM ON", "4.21", "power.PSM", "1", "Power saving on (FIX-BY-REQUEST asleep: wake up)", E::ChangesOutput, "RQUERY", "07"},
    {"PSMOFF", "4.21", "power.PSM", "0", "Power saving off", E::ChangesOutput, "RQUERY", "69"},
    {"ELEV05", "4.22", "nav.ELEV", "5", "Elevation mask 5 deg", E::None, "", "77"},
    {"ELEV06", "4.22", "nav.ELEV", "6", "Elevation mask 6 deg", E::None, "", "74"},
    {"ELEV07", "4.22", "nav.ELEV", "7", "Elevation mask 7 deg", E::None, "", "75"},
    {"ELEV08", "4.22", "nav.ELEV", "8", "Elevation mask 8 deg", E::None, "", "7A"},
    {"ELEV09", "4.22", "nav.ELEV", "9", "Elevation mask 9 deg", E::None, "", "7B"},
    {"ELEV10", "4.22", "nav.ELEV", "10", "Elevation mask 10 deg", E::None, "", "73"},
    {"ELEV11", "4.22", "nav.ELEV", "11", "Elevation mask 11 deg", E::None, "", "72"},
    {"ELEV12", "4.22", "nav.ELEV", "12", "Elevation mask 12 deg", E::None, "", "71"},
    {"ELEV13", "4.22", "nav.ELEV", "13", "Elevation mask 13 deg", E::None, "", "70"},
    {"ELEV14", "4.22", "nav.ELEV", "14", "Elevation mask 14 deg", E::None, "", "77"},
    {"ELEV15", "4.22", "nav.ELEV", "15", "Elevation mask 15 deg", E::None, "", "76"},
    {"DATP90", "4.23", "nav.DAT", "P90", "Datum PZ-90.11", E::None, "RQUERY", "60"},
    {"DATW84", "4.23", "nav.DAT", "W84", "Datum WGS-84", E::None, "RQUERY", "62"},
    {"NVSGPS", "4.24", "nav.NVS", "GPS", "GPS only", E::None, "RQUERY", "67"},
    {"NVSGLN", "4.24", "nav.NVS", "GLN", "GLONASS only", E::None, "RQUERY", "66"},
    {"NVSMIX", "4.24", "nav.NVS", "MIX", "GLONASS+GPS+Galileo", E::None, "RQUERY", "7F"},
};
// clang-format on

std::string_view trimBlanks(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

EncodeResult fixed(std::string_view text) {
    EncodeResult r;
    if (const CommandDef *c = findCommand(text)) r.sentences.push_back(encodeCommand(*c));
    return r;
}

// One setting's set command, without the read-back query a plan adds to confirm it.
EncodeResult setting(std::string_view key, std::string value) {
    const KeyValue kv{std::string(key), std::move(value)};
    std::vector<PlannedCommand> plan;
    EncodeResult r;
    if (Refusal why = planWrites(dialect(), std::span<const KeyValue>(&kv, 1), plan); !why.empty())
        r.refuse(std::move(why));
    else
        r = plan.front().command->write(plan.front().values);
    return r;
}

} // namespace

std::span<const CommandDef> commands() {
    return kCommands;
}

const CommandDef *findCommand(std::string_view text) {
    text = trimBlanks(text);
    // The spec prints "NMEA V2" / "NMEA V4"; the checksums prove "NMEAV2" / "NMEAV4".
    if (text == "NMEA V2") text = "NMEAV2";
    if (text == "NMEA V4") text = "NMEAV4";
    for (const auto &c : kCommands)
        if (c.text == text) return &c;
    return nullptr;
}

const CommandDef *findCommandFor(std::string_view settingKey, std::string_view value) {
    for (const auto &c : kCommands)
        if (c.settingKey == settingKey && c.value == value) return &c;
    return nullptr;
}

std::string encodeCommand(const CommandDef &c) {
    std::string body(kAddress);
    body += ',';
    body += c.text;
    return buildSentence(body);
}

EncodeResult encodeSwitchToBinary() {
    return fixed("SWPROT");
}
EncodeResult encodeSaveAlmanacs() {
    return fixed("SAVEFL");
}
EncodeResult encodeColdStart() {
    return fixed("CSTART");
}
EncodeResult encodeWarmStart() {
    return fixed("WSTART");
}
EncodeResult encodeHotStart() {
    return fixed("HSTART");
}
EncodeResult encodeStatusQuery() {
    return fixed("RQUERY");
}
EncodeResult encodeOutputQuery() {
    return fixed("NQUERY");
}
EncodeResult encodeBaudRate(int baud) {
    return setting("port.BDR", std::to_string(baud));
}
EncodeResult encodeStopBits(int bits) {
    return setting("port.STOP", std::to_string(bits));
}
EncodeResult encodeOutput(std::string_view msg, bool on) {
    return setting("output." + std::string(msg), on ? "1" : "0");
}
EncodeResult encodeNmeaVersion(int v) {
    return setting("output.NMEAV", std::to_string(v));
}
EncodeResult encodeRate(int hz) {
    return setting("output.RATE", std::to_string(hz));
}
EncodeResult encodePowerSaving(bool on) {
    return setting("power.PSM", on ? "1" : "0");
}
EncodeResult encodeElevationMask(int deg) {
    return setting("nav.ELEV", std::to_string(deg));
}
EncodeResult encodeDatum(std::string_view d) {
    return setting("nav.DAT", std::string(d));
}
EncodeResult encodeConstellations(std::string_view m) {
    return setting("nav.NVS", std::string(m));
}

} // namespace gnss::geostar
