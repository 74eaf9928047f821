#pragma once
// A preset's values as settings to apply. The presets themselves are data of each dialect record
// (Dialect::presets); applying one is applying its values (only what differs is sent).
#include "core/dialect.h"

#include <vector>

namespace gnss::config {

std::vector<KeyValue> presetValues(const Preset &p);

} // namespace gnss::config
