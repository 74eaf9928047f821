#pragma once
// GeoS-5 settings as data: what can be set with the section 4 commands, and where RQUERY /
// NQUERY report the current value (write-only where neither does).
#include "core/dialect_hooks.h"
#include "core/message.h"
#include "core/refusal.h"
#include "core/settings_schema.h"

#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace gnss::geostar {

struct Nquery;
struct Rquery;

std::span<const SettingDef> settingsSchema();

// Each row names its command (core/setting_command.h): the set command of the section 4 table
// for its value, and the query that reports it (NQUERY, RQUERY, or none: write-only). The set
// commands are answered with nothing: a plan reads them back as their confirmation.

// Setting values carried by a decoded $GPSGG,RQUERY or $GPSGG,NQUERY reply, and by a decoded set
// command (the setting and value its row of the command table names; actions and queries carry
// none), so that a receiver applies what it is sent through the same reading
// (geostar_settings_report.cpp).
ExtractSettingsHook extractSettings;

// The inverse, for a receiver that answers (the simulator): the settings in force, by key, written
// into the reply fields that report them. RQUERY: output.RATE (configuration register 1 bits
// 19:18), power.PSM (bit 24), nav.NVS (bits 2:0), nav.DAT (register 2 bits 15:14). NQUERY:
// output.RATE, output.NMEAV and each output.<message>: one that is off gets code 0, one that is
// on keeps the code it has (1, 2, 3 or R: how often is the receiver's own choice; a setting says
// only on or off), R when it has none. Settings not in `values` leave their fields as they are;
// a value the schema refuses is refused, and the reply is then left as it was.
using SettingValues = std::map<std::string, std::string, std::less<>>;
Refusal reportSettings(const SettingValues &values, Rquery &reply);
Refusal reportSettings(const SettingValues &values, Nquery &reply);

} // namespace gnss::geostar
