#pragma once
// Private helpers of the NVS encoders: validation against the schema and result building.
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_schema.h"

#include "core/sentence_builder.h"

#include <string>
#include <string_view>

namespace gnss::nvs {

// Validates `value` against the schema row `key` (empty when valid).
Refusal checkSetting(std::string_view key, std::string_view value);
// "<name>: <v> is out of range; accepted: <min>..<max>" when v is outside [min, max].
std::string checkRange(std::string_view name, long long v, long long min, long long max);
// "<name>: '<c>' is not one of: <accepted>" when c is not in `accepted`.
std::string checkLetter(std::string_view name, char c, std::string_view accepted);

inline EncodeResult refuse(Refusal why) {
    EncodeResult r;
    r.refuse(std::move(why));
    return r;
}
inline EncodeResult built(std::string_view body) {
    return {{buildSentence(body)}, {}};
}

} // namespace gnss::nvs
