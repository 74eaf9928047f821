#include "json_writer.h"

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

JsonWriter &JsonWriter::beginObject() {
    separator();
    out_.push_back('{');
    needComma_ = false;
    return *this;
}
JsonWriter &JsonWriter::endObject() {
    out_.push_back('}');
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::beginArray() {
    separator();
    out_.push_back('[');
    needComma_ = false;
    return *this;
}
JsonWriter &JsonWriter::endArray() {
    out_.push_back(']');
    needComma_ = true;
    return *this;
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
    separator();
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, d);
    out_.append(buf, r.ptr);
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::value(std::int64_t i) {
    separator();
    char buf[24];
    auto r = std::to_chars(buf, buf + sizeof buf, i);
    out_.append(buf, r.ptr);
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::value(std::uint64_t i) {
    separator();
    char buf[24];
    auto r = std::to_chars(buf, buf + sizeof buf, i);
    out_.append(buf, r.ptr);
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::value(bool b) {
    separator();
    out_ += b ? "true" : "false";
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::null() {
    separator();
    out_ += "null";
    needComma_ = true;
    return *this;
}
JsonWriter &JsonWriter::raw(std::string_view text) {
    separator();
    out_ += text;
    needComma_ = true;
    return *this;
}

} // namespace gnss
