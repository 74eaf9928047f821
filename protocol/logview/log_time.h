#pragma once
// Times of the log viewer in text: what epochs show, and what users type for --from/--to.
#include "logview/epoch_record.h"

#include <optional>
#include <string>
#include <string_view>

namespace gnss::logview {

// A time a user gave: a whole UTC time ("2024-03-15T10:00:00Z", "2024-03-15 10:00:00.5") or a
// time of day ("10:00:00", "10:00", "9:42"), or an epoch number ("#1200").
struct TimeSpec {
    enum class Kind { Utc, TimeOfDay, Epoch } kind = Kind::Utc;
    std::int64_t ms = 0;     // Utc: ms since 1970; TimeOfDay: ms since midnight
    std::uint64_t epoch = 0; // Epoch
};
std::optional<TimeSpec> parseTimeSpec(std::string_view text);

// The fix badge's words for a fix type: "no fix", "estimated", "2D", "3D", "DGNSS", "RTK float",
// "RTK fixed", "fixed position", "simulator".
std::string_view fixWords(FixType f);

} // namespace gnss::logview
