#pragma once
#include "core/message.h"

namespace gnss {
struct ReceiverState;
}

namespace gnss::nemerix {

// The dialect's updateState hook (see core/dialect.h).
bool updateState(const Message &m, ReceiverState &state);

} // namespace gnss::nemerix
