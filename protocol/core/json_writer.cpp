#include "core/json_writer.h"

#include <charconv>
#include <cmath>

namespace gnss {

namespace {

// The length of the valid UTF-8 sequence at s[i] (2..4), or 0 when it is not one (a stray
// byte, an overlong form, a surrogate, past U+10FFFF, cut short).
std::size_t utf8Sequence(std::string_view s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = b(i);
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF; // the second byte's range
    if (c >= 0xC2 && c <= 0xDF) {
        n = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;
        if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;
        if (c == 0xF4) hi = 0x8F;
    } else {
        return 0;
    }
    if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
    return n;
}

// A byte written into a JSON string as it is.
bool isPlainJsonByte(unsigned char u) {
    return u >= 0x20 && u < 0x7F && u != '"' && u != '\\';
}

} // namespace

void appendJsonString(std::string &out, std::string_view s) {
    out.push_back('"');
    std::size_t i = 0;
    while (i < s.size()) {
        // Printable ASCII other than the two escaped characters goes out as one run.
        std::size_t plain = i;
        while (plain < s.size() && isPlainJsonByte(static_cast<unsigned char>(s[plain]))) ++plain;
        out.append(s.data() + i, plain - i);
        if (plain == s.size()) break;
        i = plain;
        const char c = s[i];
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default: {
            const auto u = static_cast<unsigned char>(c);
            // Text in UTF-8 stays as it is; a byte that is not text (a control character, or
            // junk from a serial line) is written as the code point of its value.
            if (u >= 0x80) {
                if (const std::size_t n = utf8Sequence(s, i)) {
                    out.append(s.substr(i, n));
                    i += n;
                    continue;
                }
            }
            static const char hex[] = "0123456789abcdef";
            out += "\\u00";
            out.push_back(hex[u >> 4]);
            out.push_back(hex[u & 15]);
        }
        }
        ++i;
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
