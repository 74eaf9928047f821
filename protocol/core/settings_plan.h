#pragma once
// Settings plans from the schema's rows: a change or a read-back becomes the sentences of the
// commands the rows name (setting_command.h), in the commands' order. The one implementation
// behind every dialect's settings: the engine, `gnss-cli encode`, profiles and the simulator.
#include "core/setting_command.h"
#include "core/settings_schema.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss {

struct Dialect;

// One command of a plan and the settings it carries (keys as the schema spells them).
struct PlannedCommand {
    const SettingCommand *command = nullptr;
    std::vector<KeyValue> values;
};

// An unknown or ambiguous setting of `d`, refused with the keys it could mean (several rows
// share the name) or the nearest ones.
Refusal unknownSetting(const Dialect &d, std::string_view key);

// Groups `values` by command, in plan order. Refuses an unknown key, a setting that cannot be
// set, a value its command does not take, or a setting given twice; plans nothing then.
Refusal planWrites(const Dialect &d, std::span<const KeyValue> values,
                   std::vector<PlannedCommand> &out);

// The sentences that write `values`, in order; nothing is built when anything is refused.
// Identical sentences are sent once (commands confirmed by one query).
EncodeResult encodeSettings(const Dialect &d, std::span<const KeyValue> values);

// The sentences that read `keys` back, each query once. Refuses an unknown or write-only key.
EncodeResult encodeQueries(const Dialect &d, std::span<const std::string> keys);

// Every readable setting's key, in schema order.
std::vector<std::string> readableKeys(const Dialect &d);

// Every command the dialect's record can send, as sentence bodies without '$' and checksum
// ("GPSGG,GGA ON"), each once, in first-seen order: its probe, the queries of its readable
// settings, what its schema rows write for each value they can take (each option, on and off,
// every integer of a range of at most 64), and its actions. Settings that take free values
// (text, reals, wide ranges) give none. For a family whose console completion is its whole
// command set (GeoStar's), the record's commandNames come from here.
std::vector<std::string> commandBodies(const Dialect &d);

} // namespace gnss
