#pragma once
// GeoS-5 settings as data: what can be set with the section 4 commands, and where RQUERY /
// NQUERY report the current value (write-only where neither does).
#include "core/message.h"
#include "core/settings_schema.h"

#include <span>
#include <string>
#include <vector>

namespace gnss::geostar {

std::span<const SettingDef> settingsSchema();

// Each row names its command (core/setting_command.h): the set command of the section 4 table
// for its value, and the query that reports it (NQUERY, RQUERY, or none: write-only). The set
// commands are answered with nothing: a plan reads them back as their confirmation.
// Setting values carried by a decoded $GPSGG,RQUERY or $GPSGG,NQUERY reply.
void extractSettings(const Message &reply, std::vector<KeyValue> &out);

} // namespace gnss::geostar
