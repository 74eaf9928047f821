#pragma once
// The NVS settings schema (one table, nvs_schema.cpp) and the dialect's generic settings
// functions built on it (nvs_settings.cpp).
#include "core/message.h"
#include "core/setting_command.h"
#include "core/settings_schema.h"

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

// Dialect hook: setting values carried by a decoded reply.
void extractSettings(const Message &reply, std::vector<KeyValue> &out);

} // namespace gnss::nvs
