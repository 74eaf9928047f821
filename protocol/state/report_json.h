#pragma once
// Helpers for the dialects' updateState hooks: a message's JSON, for ReceiverState::reports.
#include "core/message.h"
#include "state/receiver_state.h"

#include <string>

namespace gnss {

inline std::string messageJson(const Message &m) {
    std::string out;
    JsonWriter w(out);
    m.writeJson(w);
    return out;
}

// A message shown as it is: when `m` is a T, its JSON becomes the report `title` (true);
// otherwise nothing changes (false).
template <class T> bool keepReport(const Message &m, ReceiverState &st, const std::string &title) {
    if (!message_cast<T>(m)) return false;
    st.reports[title] = messageJson(m);
    return true;
}

} // namespace gnss
