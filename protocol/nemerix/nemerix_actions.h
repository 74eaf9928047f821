#pragma once
// VT002 receiver-wide actions, presets and port speeds (data of the dialect record).
#include "core/dialect.h"

namespace gnss::nemerix {

std::span<const ActionDef> actions();
std::span<const Preset> presets();
std::span<const int> supportedBauds();

} // namespace gnss::nemerix
