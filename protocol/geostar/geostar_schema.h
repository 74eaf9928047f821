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

// The commands that set `values` (validated first: nothing is built on error), then the queries
// whose replies confirm them (the receiver answers set commands with nothing; an RQUERY/NQUERY
// reading afterwards is the confirmation). Commands that reset the receiver, change the port
// speed or leave NMEA come last.
EncodeResult encodeSettings(std::span<const KeyValue> values);
// Only the set commands, without the confirming queries.
EncodeResult encodeSettingCommands(std::span<const KeyValue> values);
// The queries that read the given settings back ("RQUERY", "NQUERY" and "all" are accepted
// too). Write-only settings are refused with a message.
EncodeResult encodeQueries(std::span<const std::string> keys);
// Setting values carried by a decoded $GPSGG,RQUERY or $GPSGG,NQUERY reply.
void extractSettings(const Message &reply, std::vector<KeyValue> &out);

} // namespace gnss::geostar
