#pragma once
// A refusal (core/refusal.h) in the user's language: its template translated (context
// "Refusal") and filled with its arguments, the dialect's own words among them (a unit, "deg")
// translated too; as written when it has no template.
#include "core/settings_schema.h"

#include <QString>

#include <string_view>

namespace gnss::config {

QString refusalText(const Refusal &r, std::string_view dialectId = {});
// An encoder's refusal: the translated template when it gave one for this error, else the error.
QString refusalText(const EncodeResult &r, std::string_view dialectId = {});
// A decoder's word on a sentence (SentenceEvent::error and ::problem): translated the same way,
// a phrase without arguments ("checksum missing") looked up as it is.
QString refusalText(std::string_view error, const Refusal *problem);

} // namespace gnss::config
