#pragma once
// The NVS settings schema (one table, nvs_schema.cpp) and the dialect's generic settings
// functions built on it (nvs_settings.cpp).
#include "core/message.h"
#include "core/setting_command.h"
#include "core/settings_schema.h"
#include "nvs/nvs_messages.h"

#include <optional>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::nvs {

// Every configurable parameter: the 33 PNVGRTK parameters of Table 4 ("rtk.MODE" ...
// "rtk.INITGPSWEEK"), PNVGNME ("nmea.*"), PNVGRZA per port ("port.COM1.baud", ...), PNVGRZB
// output lists per port ("output.COM1", ...), PNVGPPS ("pps.*") and the PNVGIDL station list
// ("idl.mode", "idl.stations").
std::span<const SettingDef> settingsSchema();

// Port names used in keys, indexed by the spec's port number (1 COM1, 2 COM2, 3 USB).
std::string_view portName(int port);
int portNumber(std::string_view name); // -1 when unknown

// The commands the rows name (nvs_settings.cpp).
extern const SettingCommand kRtkCommand;        // PNVGRTK: every Table 4 parameter
extern const SettingCommand kIdlModeCommand;    // PNVGIDL,MODE
extern const SettingCommand kStationsCommand;   // PNVGIDL,CLEAR + ADD..., read with SHOW
extern const SettingCommand kPpsCommand;        // PNVGPPS
extern const SettingCommand kNmeCommand;        // PNVGNME
extern const SettingCommand kOutputCommands[3]; // PNVGRZB per port (COM1, COM2, USB)
extern const SettingCommand kPortCommands[3];   // PNVGRZA per port

// The values of the list settings, as their rows' help describes them (nvs_settings.cpp).
// output.<port>: "RMC:1;GSV:5;PNVGTST:10" (a bare address means rate 1).
Refusal parseOutputList(std::string_view key, std::string_view value, std::vector<RzbEntry> &out);
std::string formatOutputList(std::span<const RzbEntry> entries);
// idl.stations: "3:0.0720;43" (a bare id: the ICB in force when it is added), at most 32.
struct Station {
    int id = 0;
    std::optional<double> icb;
};
Refusal parseStations(std::string_view value, std::vector<Station> &out);
std::string formatStations(std::span<const Station> stations); // ICBs with 4 decimals

// Dialect hook: setting values carried by a decoded reply.
void extractSettings(const Message &reply, std::vector<KeyValue> &out);

} // namespace gnss::nvs
