// The address prefix of outgoing commands, and the helpers every encoder ends with.
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"

namespace gnss::nemerix {

std::string checkPrefix(std::string_view prefix) {
    if (checkAddressPrefix(prefix).empty()) return {};
    return "prefix: '" + std::string(prefix) +
           "' is not usable; accepted: 'P' followed by 1 to 8 upper-case letters or digits "
           "(default PNMRX)";
}

std::string applyPrefix(std::string_view sentence, std::string_view prefix) {
    if (!checkPrefix(prefix).empty()) return {};
    if (!sentence.starts_with('$')) return std::string(sentence);
    return renameAddressPrefix(sentence, "PNMRX", prefix);
}

EncodeResult buildCommand(std::string_view number, std::string_view fields,
                          std::string_view prefix) {
    EncodeResult r;
    r.error = checkPrefix(prefix);
    if (!r.ok()) return r;
    std::string body(prefix);
    body.append(number);
    body.append(fields);
    r.sentences.push_back(buildSentence(body));
    return r;
}

Refusal checkFieldText(std::string_view name, std::string_view text) {
    for (char c : text)
        if (c == ',' || c == '*' || c == '$' || c == '!' || static_cast<unsigned char>(c) < 0x20 ||
            static_cast<unsigned char>(c) >= 0x7F)
            return refusal(
                    QT_TRANSLATE_NOOP("Refusal", "%1: character not allowed in a value: '%2'"),
                    {std::string(name), std::string(1, c)});
    return {};
}

EncodeResult encodeStopCore(std::string_view prefix) {
    return buildCommand("113", {}, prefix);
}
EncodeResult encodeVersionQuery(std::string_view prefix) {
    return buildCommand("600", {}, prefix);
}
EncodeResult encodeIspMode(std::string_view prefix) {
    return buildCommand("601", {}, prefix);
}
EncodeResult encodeSettingsQuery(std::string_view prefix) {
    return buildCommand("603", {}, prefix);
}

} // namespace gnss::nemerix
