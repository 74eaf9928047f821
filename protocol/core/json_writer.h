#pragma once
// A minimal streaming JSON writer (objects, arrays, strings, numbers, null). Commas are placed
// automatically. Used by `gnss-cli` output and by each message's writeJson().
#include "core/field_types.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gnss {

class JsonWriter {
public:
    explicit JsonWriter(std::string &out) : out_(out) {}

    JsonWriter &beginObject();
    JsonWriter &endObject();
    JsonWriter &beginArray();
    JsonWriter &endArray();
    JsonWriter &key(std::string_view k);

    JsonWriter &value(std::string_view s);
    JsonWriter &value(const char *s) { return value(std::string_view(s)); }
    JsonWriter &value(double d);
    JsonWriter &value(std::int64_t i);
    JsonWriter &value(int i) { return value(static_cast<std::int64_t>(i)); }
    JsonWriter &value(unsigned i) { return value(static_cast<std::int64_t>(i)); }
    JsonWriter &value(std::uint64_t i);
    JsonWriter &value(bool b);
    JsonWriter &value(char c) { return value(std::string_view(&c, 1)); }
    JsonWriter &null();
    template <class T> JsonWriter &value(const std::optional<T> &v) {
        return v ? value(*v) : null();
    }
    JsonWriter &value(const TimeOfDay &t) { return value(std::string_view(t.toString())); }
    JsonWriter &value(const Date &d) { return value(std::string_view(d.toString())); }
    // A number already formatted (kept exactly as the receiver printed it).
    JsonWriter &raw(std::string_view text);

    template <class T> JsonWriter &field(std::string_view k, const T &v) {
        key(k);
        return value(v);
    }

private:
    void separator();
    JsonWriter &open(char bracket);
    JsonWriter &close(char bracket);
    std::string &out_;
    bool needComma_ = false;
    bool afterKey_ = false;
};

// Appends `s` as a JSON string literal (quoted and escaped): UTF-8 text as it is, any other byte
// (control characters, junk) as \u00XX, the code point of its value.
void appendJsonString(std::string &out, std::string_view s);

} // namespace gnss
