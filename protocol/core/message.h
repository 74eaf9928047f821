#pragma once
// Message: the typed result of decoding one sentence.
//
// Each message struct derives from Message, names its MessageType (a static tag, so a new
// message needs no central enum) and writes its decoded values as JSON. Consumers that need one
// type use message_cast<T>(m); the rest treat messages generically.
#include "core/json_writer.h"

#include <string_view>

namespace gnss {

struct MessageType {
    std::string_view name; // "GGA", "PNVGRTK", "GPSGG,RQUERY"
};

struct Message {
    explicit Message(const MessageType &t) : type(&t) {}
    Message(const Message &) = default;
    Message &operator=(const Message &) = default;
    virtual ~Message() = default;
    // Writes the decoded values as one JSON object (snake_case keys).
    virtual void writeJson(JsonWriter &w) const = 0;

    const MessageType *type;
};

template <class T> const T *message_cast(const Message &m) {
    return m.type == &T::kType ? static_cast<const T *>(&m) : nullptr;
}

} // namespace gnss
