#include "config/presets.h"

#include <string>

namespace gnss::config {

std::vector<KeyValue> presetValues(const Preset &p) {
    std::vector<KeyValue> out;
    for (const auto &v : p.values) out.push_back({std::string(v.key), std::string(v.value)});
    return out;
}

} // namespace gnss::config
