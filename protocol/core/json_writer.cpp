#include "core/json_writer.h"

#include <charconv>
#include <cmath>

namespace gnss {

void appendJsonString(std::string &out, std::string_view s) {
    out.push_back('"');
    for (char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
                static const char hex[] = "0123456789abcdef";
                const auto u = static_cast<unsigned char>(c);
                out += "\\u00";
                out.push_back(hex[u >> 4]);
                out.push_back(hex[u & 15]);
            } else {
                out.push_back(c);
            }
        }
    }
    out.push_back('"');
}

void JsonWriter::separator() {
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (needComma_) out_.push_back(',');
}

namespace {

// A number as std::to_chars writes it: the shortest form that reads back the same.
template <class T> JsonWriter &number(JsonWriter &w, T v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return w.raw(std::string_view(buf, static_cast<std::size_t>(r.ptr - buf)));
}

} // namespace

JsonWriter &JsonWriter::open(char bracket) {
    separator();
    out_.push_back(bracket);
    needComma_ = false;
    return *this;
}
JsonWriter &JsonWriter::close(char bracket) {
    out_.push_back(bracket);
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::beginObject() {
    return open('{');
}
JsonWriter &JsonWriter::endObject() {
    return close('}');
}
JsonWriter &JsonWriter::beginArray() {
    return open('[');
}
JsonWriter &JsonWriter::endArray() {
    return close(']');
}
JsonWriter &JsonWriter::key(std::string_view k) {
    separator();
    appendJsonString(out_, k);
    out_.push_back(':');
    afterKey_ = true;
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::value(std::string_view s) {
    separator();
    appendJsonString(out_, s);
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::value(double d) {
    if (!std::isfinite(d)) return null();
    return number(*this, d);
}
JsonWriter &JsonWriter::value(std::int64_t i) {
    return number(*this, i);
}
JsonWriter &JsonWriter::value(std::uint64_t i) {
    return number(*this, i);
}
JsonWriter &JsonWriter::value(bool b) {
    return raw(b ? "true" : "false");
}
JsonWriter &JsonWriter::null() {
    return raw("null");
}
JsonWriter &JsonWriter::raw(std::string_view text) {
    separator();
    out_ += text;
    needComma_ = true;
    return *this;
}

} // namespace gnss
