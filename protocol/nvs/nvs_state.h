#pragma once
#include "core/dialect_hooks.h"

namespace gnss::nvs {

UpdateStateHook updateState; // the dialect's updateState hook (see core/dialect.h)

} // namespace gnss::nvs
