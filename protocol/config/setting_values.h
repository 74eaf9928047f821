#pragma once
// Setting values as the receiver and the user write them: whether two spellings mean the same
// value, and which settings are actions rather than settings. Plain C++ over the schema.
#include "core/settings_schema.h"

#include <string>
#include <string_view>

namespace gnss::config {

// Whether `wanted` (what was set) and `reported` (what the receiver read back) are the same
// value of `def`: numbers compare as numbers, to the precision the receiver reported ("0.05" ==
// "0.050", "05" == "5"; a coordinate reported to 4 decimals matches within half the last digit);
// "ON"/"1"/"true" are one boolean; lists and coordinates compare item by item (';' ',' ':' split).
bool sameValue(const SettingDef &def, std::string_view wanted, std::string_view reported);

// Schema rows whose key starts with "action." are one-off commands (restart, save almanacs,
// switch protocol): not settings to read, export or compare. The engine runs them as actions.
bool isAction(const SettingDef &def);
// Settings the receiver reports (read back) / accepts (written), actions excluded.
bool isReadable(const SettingDef &def);
bool isWritable(const SettingDef &def);

std::string trimmed(std::string_view s);

} // namespace gnss::config
