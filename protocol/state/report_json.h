#pragma once
// Helper for the dialects' updateState hooks: a message's JSON, for ReceiverState::reports.
#include "core/message.h"

#include <string>

namespace gnss {

inline std::string messageJson(const Message &m) {
    std::string out;
    JsonWriter w(out);
    m.writeJson(w);
    return out;
}

} // namespace gnss
