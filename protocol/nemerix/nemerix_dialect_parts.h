#pragma once
// The pieces the dialect record (nemerix_dialect.cpp) is assembled from, one file each.
#include "core/dialect.h"
#include "core/dialect_hooks.h"
#include "core/setting_command.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::nemerix {

std::span<const SentenceRule> sentenceRules(); // nemerix_rules.cpp
std::span<const SettingDef> settingsSchema();  // nemerix_schema.cpp
std::span<const ReplyRule> replyRules();       // nemerix_reply_rules.cpp
// Settings a decoded PNMRX603 report or a command carries (nemerix_settings_values.cpp).
ExtractSettingsHook extractSettings;

// The ids of an output.sequence value ("GGA;GSA", ',' accepted too), and the schema key of a
// PNMRX110 mask id (nullptr past the table) (nemerix_settings.cpp).
std::vector<std::string> sequenceIds(std::string_view list);
const char *fixMaskKey(int id);

// The commands the schema's rows name (nemerix_settings.cpp).
extern const SettingCommand kDatumCommand;        // PNMRX106
extern const SettingCommand kFixMaskCommand;      // PNMRX110
extern const SettingCommand kNavInitCommand;      // PNMRX101
extern const SettingCommand kPowerCommand;        // PNMRX112
extern const SettingCommand kSequenceCommand;     // PNMRX108
extern const SettingCommand kRatesCommand;        // PNMRX103
extern const SettingCommand kNemerixRatesCommand; // PNMRX107
extern const SettingCommand kSerialCommand;       // PNMRX100

} // namespace gnss::nemerix
