#pragma once
#include "core/dialect_hooks.h"

namespace gnss::geostar {

UpdateStateHook updateState; // the dialect's updateState hook (see core/dialect.h)

} // namespace gnss::geostar
