#pragma once
// The pieces the dialect record (nemerix_dialect.cpp) is assembled from, one file each.
#include "core/dialect.h"

#include <span>
#include <string>
#include <vector>

namespace gnss::nemerix {

std::span<const SentenceRule> sentenceRules();                          // nemerix_rules.cpp
std::span<const SettingDef> settingsSchema();                           // nemerix_schema.cpp
std::span<const ReplyRule> replyRules();                                // nemerix_reply_rules.cpp
EncodeResult encodeSettings(std::span<const KeyValue> values);          // nemerix_settings.cpp
EncodeResult encodeQueries(std::span<const std::string> keys);          // nemerix_settings.cpp
void extractSettings(const Message &reply, std::vector<KeyValue> &out); // nemerix_settings.cpp

} // namespace gnss::nemerix
