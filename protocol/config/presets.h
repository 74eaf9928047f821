#pragma once
// Presets for common jobs, as data (presets.cpp): a named set of setting values for one dialect.
// Applying a preset is applying its values (only what differs is sent).
#include "core/settings_schema.h"

#include <span>
#include <string_view>
#include <vector>

namespace gnss::config {

struct PresetValue {
    std::string_view key, value;
};

struct Preset {
    std::string_view dialect;
    std::string_view name;
    std::string_view description;
    std::span<const PresetValue> values;
};

std::span<const Preset> presetTable();
std::vector<const Preset *> presetsFor(std::string_view dialect);
std::vector<KeyValue> presetValues(const Preset &p);

} // namespace gnss::config
