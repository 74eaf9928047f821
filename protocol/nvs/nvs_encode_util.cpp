#include "nvs/nvs_encode_util.h"

namespace gnss::nvs {

Refusal checkSetting(std::string_view key, std::string_view value) {
    const SettingDef *def = findSetting(settingsSchema(), key);
    if (!def)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "unknown setting '%1'"), {std::string(key)});
    return validateSetting(*def, value);
}

std::string checkRange(std::string_view name, long long v, long long min, long long max) {
    if (v >= min && v <= max) return {};
    return std::string(name) + ": " + std::to_string(v) +
           " is out of range; accepted: " + std::to_string(min) + ".." + std::to_string(max);
}

std::string checkLetter(std::string_view name, char c, std::string_view accepted) {
    if (c != '\0' && c != ',' && accepted.find(c) != std::string_view::npos) return {};
    std::string list;
    for (char a : accepted) {
        if (!list.empty()) list += ", ";
        list += a;
    }
    std::string shown = (c >= 0x20 && c < 0x7F) ? std::string(1, c) : std::string("?");
    return std::string(name) + ": '" + shown + "' is not one of: " + list;
}

} // namespace gnss::nvs
