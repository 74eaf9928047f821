#pragma once
// The 24 input commands of section 4 of the GeoS-5 NMEA protocol v4.0, as one table of every
// concrete command text the receiver accepts ("BDR115", "GGA ON", "ELEV05", ...).
//
// Every command is `$GPSGG,<text>*hh` (docs/spec-notes.md: the spec's `$GPGSGG,` / `$GPGSSG,` /
// `$GPGG,` are misprints; the checksums prove `GPSGG`). Six-character texts keep their inner blank
// ("GGA ON", "PSM ON"); "NMEA V2" is really "NMEAV2".
//
// The table is the single source of truth: the GPSGG decoder names what a command does from it,
// the settings encoder finds the command for a (setting, value) pair in it, and the reply rules
// take each command's effect from it.
#include "core/dialect.h"
#include "core/settings_schema.h"

#include <span>
#include <string>
#include <string_view>

namespace gnss::geostar {

inline constexpr std::string_view kAddress = "GPSGG";

struct CommandDef {
    std::string_view text;       // first field: "BDR115"
    std::string_view section;    // spec section: "4.8"
    std::string_view settingKey; // the setting it writes ("port.BDR"), or an action key
    std::string_view value;      // the value of that setting it writes ("115200")
    std::string_view description;
    CommandEffect effect = CommandEffect::None;
    // The query whose reply confirms the change ("NQUERY", "RQUERY"), empty when the receiver
    // reports nothing that would confirm it.
    std::string_view confirmedBy;
    // The checksum the spec prints for this command (every command has a printed example).
    std::string_view specChecksum;
};

// Every concrete command, in the order of section 4.
std::span<const CommandDef> commands();

// The command with this text. Also accepts the spec's spelling "NMEA V2" / "NMEA V4" and
// surrounding blanks. nullptr when unknown.
const CommandDef *findCommand(std::string_view text);

// The command that sets `settingKey` to `value` (value as in the table: "115200", "ON", "5").
const CommandDef *findCommandFor(std::string_view settingKey, std::string_view value);

// "$GPSGG,<text>*hh".
std::string encodeCommand(const CommandDef &c);

// Typed encoders, one per command of section 4. Values the receiver does not accept are refused
// with a message naming the parameter and the accepted values; nothing is built then.
EncodeResult encodeSwitchToBinary();                      // 4.1 SWPROT
EncodeResult encodeSaveAlmanacs();                        // 4.2 SAVEFL
EncodeResult encodeColdStart();                           // 4.3 CSTART
EncodeResult encodeWarmStart();                           // 4.4 WSTART
EncodeResult encodeHotStart();                            // 4.5 HSTART
EncodeResult encodeStatusQuery();                         // 4.6 RQUERY
EncodeResult encodeOutputQuery();                         // 4.7 NQUERY
EncodeResult encodeBaudRate(int baud);                    // 4.8 BDR---
EncodeResult encodeStopBits(int bits);                    // 4.9 STOP--
EncodeResult encodeOutput(std::string_view msg, bool on); // 4.10-4.18 GGA..RLM ON/OFF
EncodeResult encodeNmeaVersion(int version);              // 4.19 NMEAV2 / NMEAV4
EncodeResult encodeRate(int hz);                          // 4.20 RATE--
EncodeResult encodePowerSaving(bool on);                  // 4.21 PSM ON / PSMOFF
EncodeResult encodeElevationMask(int degrees);            // 4.22 ELEV--
EncodeResult encodeDatum(std::string_view datum);         // 4.23 "W84" / "P90"
EncodeResult encodeConstellations(std::string_view mode); // 4.24 "GPS" / "GLN" / "MIX"

} // namespace gnss::geostar
