#pragma once
// Settings schema: every configurable parameter of a receiver, as data.
//
// One table per dialect is the single source of truth that the settings forms, `gnss-cli schema`,
// `gnss-cli encode`, configuration profiles and the simulator all read.
#include "core/refusal.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss {

enum class SettingType {
    Bool,        // "0"/"1" (or the dialect's ON/OFF)
    Integer,     // min/max apply
    Real,        // min/max apply
    Enum,        // one of options[].value
    Text,        // free text (station ids, names)
    Coordinates, // several reals separated by ',' (BASEXYZ x,y,z; BASEBLH lat,lon,h)
    List,        // a list of items separated by ';' (output message lists, station lists)
};
std::string_view toString(SettingType t);

enum class SettingAccess {
    ReadWrite, // can be queried and set
    WriteOnly, // the receiver cannot report it: shown as "unknown (write-only)"
    ReadOnly,  // reported but not settable
};
std::string_view toString(SettingAccess a);

// What a setting is for, where views need it whatever the vendor calls it: the sky plot asks for
// the elevation mask, never for "rtk.ELGPS" or "nav.ELEV".
enum class SettingRole : std::uint8_t {
    None,
    ElevationMask, // degrees above the horizon below which satellites are not used
    SnrMask,       // dB-Hz below which signals are not used
    OutputRate,    // navigation/output rate, Hz
    PortSpeed,     // the speed of the port the host is on, bit/s
    // A base station (protocol/base): whatever the vendor calls them.
    BaseMode,             // rover, base at a set position, base that averages its own (options'
                          // meanings say which value is which)
    BasePosition,         // the base's antenna reference point, ECEF "X,Y,Z" in metres
    BaseStationId,        // the RTCM station id it sends (DF003)
    BaseRtcmInterval,     // seconds between the base's observables
    BaseThreshold,        // metres between the set position and its own past which it stops
    BaseAveragingMinutes, // how long the receiver averages its own position
    BaseAveragingInput,   // which of its fixes it averages
    BaseNmeaPosition,     // whose position its NMEA reports in base mode (options' meanings)
    PortSpeedOf,          // a port's speed, bit/s (SettingDef::port names the port)
    PortProtocol,         // what a port carries (SettingDef::port; options' meanings)
};

// What an option of an enumerated setting means, where a role needs to know (which value of the
// mode is a base, which protocol is RTCM 3).
enum class OptionMeaning : std::uint8_t {
    None,
    Autonomous,    // BaseMode: a receiver on its own
    Rover,         // BaseMode: an RTK rover
    BaseFixed,     // BaseMode: a base at the position set
    BaseAveraging, // BaseMode: a base that averages its own position first
    Off,           // PortProtocol: nothing
    Nmea,          // PortProtocol: NMEA 0183
    Rtcm3,         // PortProtocol: RTCM 3
    BasePosition,  // BaseNmeaPosition: the set base position
    OwnPosition,   // BaseNmeaPosition: the receiver's own fix
};

struct SettingCommand; // setting_command.h

struct SettingOption {
    std::string_view value; // what is sent ("1", "GPS", "ON")
    std::string_view label; // what the user reads
    OptionMeaning meaning = OptionMeaning::None;
};

struct SettingDef {
    std::string_view key;   // stable key, ends with the spec's own name: "rtk.MODE"
    std::string_view label; // short label
    std::string_view group; // settings page: "RTK engine", "Ports", ...
    SettingType type = SettingType::Integer;
    std::string_view unit; // "Hz", "deg", "m", "s", "" if none
    std::optional<double> min;
    std::optional<double> max;
    std::span<const SettingOption> options;
    std::string_view defaultValue; // as text; empty when the spec gives none
    std::string_view help;         // from the spec
    SettingAccess access = SettingAccess::ReadWrite;
    std::string_view readBack; // how it is read back: the query and where the value is (help)
    std::string_view write;    // how it is written: the command template (help)
    // The command that writes it and reads it back (setting_command.h). Plans are made from
    // this, never from the texts above. nullptr: neither written nor read (not a setting).
    const SettingCommand *command = nullptr;
    SettingRole role = SettingRole::None;
    // The receiver's port a per-port setting belongs to, as the vendor numbers them (1 = COM1);
    // 0 for receiver-wide settings.
    std::uint8_t port = 0;
};

struct KeyValue {
    std::string key;
    std::string value;
};

// What an encoder produced: sentences to send in order, or why nothing may be sent.
struct EncodeResult {
    std::vector<std::string> sentences;
    std::string error; // names the parameter and the accepted range when a value is refused
    // The same as a translatable template when the encoder gave one (refuse()); a GUI shows
    // it when its text is `error`.
    Refusal refusal;
    bool ok() const { return error.empty(); }
    void refuse(Refusal r) {
        error = r.text;
        refusal = std::move(r);
    }
};

// The row `key` names, in the forms people write: the schema key ("rtk.PVTRATE") or the spec's
// own name where it is unique in the schema ("PVTRATE"), either in any case ("pvtrate"; a name
// as written first: "MODE" is rtk.MODE beside pps.mode).
// nullptr when no row, or several, answer to it (settingKeyHint says which).
const SettingDef *findSetting(std::span<const SettingDef> schema, std::string_view key);
// Why `key` names no row: the keys it could mean when several share that name (`ambiguous`),
// else up to three keys nearest to it as typed; no keys when it names one row or nothing is near.
struct SettingKeyHint {
    bool ambiguous = false;
    std::vector<std::string> keys;
    std::string list() const; // "a, b or c"
};
SettingKeyHint settingKeyHint(std::span<const SettingDef> schema, std::string_view key);
// The setting with this role (the first, when a dialect has several), nullptr when none.
const SettingDef *findSettingByRole(std::span<const SettingDef> schema, SettingRole role);

// Checks `value` against the setting's type, range and options. Returns an empty refusal when
// valid, else one naming the parameter and what it accepts.
Refusal validateSetting(const SettingDef &def, std::string_view value);

// The longest value a setting of this type may be given (a number of 5000 digits is a mistake,
// and would make a sentence no receiver reads).
std::size_t maxValueLength(SettingType t);

// Refuses `r` when one of its sentences is longer than `maxLength` with its line end.
void refuseLongSentences(EncodeResult &r, std::size_t maxLength);

} // namespace gnss
