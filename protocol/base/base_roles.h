#pragma once
// The base-station side of a dialect, found by the settings' roles (settings_schema.h), never by
// vendor keys: the mode and what each of its values means, the antenna reference point, station
// id, RTCM interval, threshold, the receiver's own averaging, and which ports can carry RTCM 3.
// A dialect can be a base when its schema has a mode with a "base at a set position" value and a
// position (today the NV08C-RTK).
#include "core/dialect.h"
#include "core/settings_schema.h"

#include <optional>
#include <string_view>
#include <vector>

namespace gnss::base {

struct BaseRoles {
    const Dialect *dialect = nullptr;
    const SettingDef *mode = nullptr;     // always there
    const SettingDef *position = nullptr; // always there (ECEF "X,Y,Z", metres)
    const SettingDef *station = nullptr;  // the others: nullptr when the dialect has none
    const SettingDef *rtcmInterval = nullptr;
    const SettingDef *threshold = nullptr;
    const SettingDef *averagingMinutes = nullptr;
    const SettingDef *averagingInput = nullptr;
    const SettingDef *nmeaPosition = nullptr;

    // The mode's value with that meaning ("1" for a base at a set position); empty when none.
    std::string_view modeValue(OptionMeaning meaning) const;
    // What a mode value means (None for a value the schema does not list).
    OptionMeaning modeMeaning(std::string_view value) const;
    // Whether the receiver averages its own position by itself (a value for it, and its time).
    bool canAverage() const;
    // The ports whose protocol can be RTCM 3, in the vendor's numbers.
    std::vector<int> rtcmPorts() const;
    const SettingDef *protocolOf(int port) const;
    const SettingDef *speedOf(int port) const;
    // The protocol value with that meaning on `port` ("7" for RTCM 3); empty when none.
    std::string_view protocolValue(int port, OptionMeaning meaning) const;
    // Every setting above that the dialect has (for reading them back), schema order.
    std::vector<std::string> keys() const;
};

// The dialect's base-station roles; nullopt when it cannot be a base.
std::optional<BaseRoles> baseRoles(const Dialect &dialect);
bool canBeBase(const Dialect &dialect);

// A word for a mode meaning, for JSON and logs: "autonomous", "rover", "base", "base_averaging".
std::string_view meaningName(OptionMeaning meaning);

} // namespace gnss::base
