#include "core/sentence_builder.h"

#include "core/framer.h"
#include "core/sentence.h"

#include <cctype>
#include <cstdio>

namespace gnss {

std::string buildSentence(std::string_view body, char start) {
    static const char hex[] = "0123456789ABCDEF";
    std::string s;
    s.reserve(body.size() + 4);
    s.push_back(start);
    s.append(body);
    const std::uint8_t cs = nmeaChecksum(body);
    s.push_back('*');
    s.push_back(hex[cs >> 4]);
    s.push_back(hex[cs & 15]);
    return s;
}

namespace {
// What a person typed, without the blanks and line end around it, and its start character
// ('$' when none was typed): returns the start, leaves the rest in `typed`.
char takeStart(std::string_view &typed) {
    while (!typed.empty() && (typed.back() == '\r' || typed.back() == '\n' || typed.back() == ' '))
        typed.remove_suffix(1);
    while (!typed.empty() && typed.front() == ' ') typed.remove_prefix(1);
    if (!typed.empty() && (typed.front() == '$' || typed.front() == '!')) {
        const char start = typed.front();
        typed.remove_prefix(1);
        return start;
    }
    return '$';
}
} // namespace

std::string completeSentence(std::string_view typed, std::string &error) {
    const char start = takeStart(typed);
    // Drop a checksum the user typed: we always compute our own.
    const auto star = typed.rfind('*');
    if (star != std::string_view::npos && typed.size() - star <= 3) typed = typed.substr(0, star);
    if (typed.empty()) {
        error = "empty sentence";
        return {};
    }
    for (char c : typed) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F ||
            c == '$' || c == '!' || c == '*') {
            error = "character not allowed in a sentence: '";
            error += c;
            error += "'";
            return {};
        }
    }
    if (typed.size() + 4 > Framer::kMaxLine) {
        error = "sentence too long";
        return {};
    }
    const auto comma = typed.find(',');
    if ((comma == std::string_view::npos ? typed.size() : comma) == 0) {
        error = "sentence has no address";
        return {};
    }
    return buildSentence(typed, start);
}

namespace {
bool isHex(char c) {
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}
} // namespace

std::string checkTypedSentence(std::string_view typed, bool fixChecksum, std::string &error,
                               std::string *note) {
    const char start = takeStart(typed);
    std::string_view given; // the checksum typed, if any
    if (const auto star = typed.find('*'); star != std::string_view::npos) {
        given = typed.substr(star + 1);
        typed = typed.substr(0, star);
        if (given.size() != 2 || !isHex(given[0]) || !isHex(given[1])) {
            error = "the checksum '*" + std::string(given) + "' is not two hex digits";
            return {};
        }
    }
    if (typed.empty()) {
        error = "empty sentence";
        return {};
    }
    for (char c : typed) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F || c == '$' || c == '!' || c == '*' || c == '\\' || c == '~') {
            error = u < 0x20 || u >= 0x7F
                            ? "a character NMEA does not allow (code " + std::to_string(u) + ")"
                            : std::string("a character NMEA reserves: '") + c + "'";
            return {};
        }
    }
    const std::string_view address = typed.substr(0, typed.find(','));
    if (address.empty()) {
        error = "the sentence has no address";
        return {};
    }
    for (char c : address)
        if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) {
            error = "the address '" + std::string(address) +
                    "' is not upper-case letters and digits";
            return {};
        }
    if (typed.size() + 4 > Framer::kMaxLine) {
        error = "sentence too long";
        return {};
    }
    std::string sentence = buildSentence(typed, start);
    const std::string_view right = std::string_view(sentence).substr(sentence.size() - 2);
    if (!given.empty() && (std::toupper(static_cast<unsigned char>(given[0])) != right[0] ||
                           std::toupper(static_cast<unsigned char>(given[1])) != right[1])) {
        if (!fixChecksum) {
            error = "the checksum *" + std::string(given) + " is wrong: it is *" +
                    std::string(right) + " (leave it out and it is added)";
            return {};
        }
        if (note) *note = "checksum *" + std::string(given) + " replaced by *" + std::string(right);
    }
    return sentence;
}

std::string checkAddressPrefix(std::string_view prefix) {
    bool ok = prefix.size() >= 2 && prefix.size() <= 9 && prefix.front() == 'P';
    for (char c : prefix)
        if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) ok = false;
    if (ok) return {};
    return "prefix '" + std::string(prefix) +
           "' is not usable: 'P' followed by 1 to 8 upper-case letters or digits";
}

std::string renameAddressPrefix(std::string_view sentence, std::string_view from,
                                std::string_view to) {
    if (sentence.size() < from.size() + 1 || sentence.substr(1, from.size()) != from)
        return std::string(sentence);
    std::string_view rest = sentence.substr(1 + from.size());
    const auto star = rest.rfind('*');
    if (star != std::string_view::npos) rest = rest.substr(0, star);
    std::string body(to);
    body.append(rest);
    return buildSentence(body, sentence.front());
}

std::string formatFixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s(buf);
    if (s == "-0" || s.rfind("-0.", 0) == 0) { // avoid "-0.000"
        bool allZero = true;
        for (char c : s)
            if (c >= '1' && c <= '9') allZero = false;
        if (allZero) s.erase(0, 1);
    }
    return s;
}

} // namespace gnss
