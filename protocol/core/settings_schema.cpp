#include "core/settings_schema.h"

#include "core/field_parse.h"
#include "core/sentence_builder.h"

#include <cmath>

namespace gnss {

std::string_view toString(SettingType t) {
    switch (t) {
    case SettingType::Bool: return "bool";
    case SettingType::Integer: return "integer";
    case SettingType::Real: return "real";
    case SettingType::Enum: return "enum";
    case SettingType::Text: return "text";
    case SettingType::Coordinates: return "coordinates";
    case SettingType::List: return "list";
    }
    return "text";
}

std::string_view toString(SettingAccess a) {
    switch (a) {
    case SettingAccess::ReadWrite: return "read-write";
    case SettingAccess::WriteOnly: return "write-only";
    case SettingAccess::ReadOnly: return "read-only";
    }
    return "read-write";
}

const SettingDef *findSetting(std::span<const SettingDef> schema, std::string_view key) {
    for (const auto &d : schema)
        if (d.key == key) return &d;
    // Users type the spec's own name ("PVTRATE" for "rtk.PVTRATE"): accept a unique suffix.
    const SettingDef *found = nullptr;
    for (const auto &d : schema) {
        if (d.key.size() > key.size() && d.key.substr(d.key.size() - key.size()) == key &&
            d.key[d.key.size() - key.size() - 1] == '.') {
            if (found) return nullptr; // ambiguous
            found = &d;
        }
    }
    return found;
}

const SettingDef *findSettingByRole(std::span<const SettingDef> schema, SettingRole role) {
    if (role == SettingRole::None) return nullptr;
    for (const auto &d : schema)
        if (d.role == role) return &d;
    return nullptr;
}

namespace {

// The accepted range without its unit: "0..90", ">= 4800".
std::string rangeText(const SettingDef &d) {
    std::string r;
    auto fmt = [&](double v) {
        return d.type == SettingType::Integer ? std::to_string(static_cast<long long>(v))
                                              : formatFixed(v, v == std::floor(v) ? 0 : 4);
    };
    if (d.min && d.max)
        r = fmt(*d.min) + ".." + fmt(*d.max);
    else if (d.min)
        r = ">= " + fmt(*d.min);
    else if (d.max)
        r = "<= " + fmt(*d.max);
    return r;
}

Refusal checkRange(const SettingDef &d, double v) {
    if ((d.min && v < *d.min) || (d.max && v > *d.max)) {
        std::vector<std::string> args{std::string(d.key),
                                      formatFixed(v, v == std::floor(v) ? 0 : 6), rangeText(d)};
        if (d.unit.empty())
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                           std::move(args));
        args.emplace_back(d.unit);
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3 %4"),
                       std::move(args));
    }
    return {};
}

} // namespace

std::size_t maxValueLength(SettingType t) {
    switch (t) {
    case SettingType::Bool:
    case SettingType::Integer:
    case SettingType::Real:
    case SettingType::Enum: return 32;
    case SettingType::Text: return 64;
    case SettingType::Coordinates: return 96;
    case SettingType::List: return 256;
    }
    return 32;
}

void refuseLongSentences(EncodeResult &r, std::size_t maxLength) {
    if (!r.ok()) return;
    for (const std::string &s : r.sentences) {
        const std::size_t n = s.size() + 2; // with "\r\n"
        if (n > maxLength) {
            r.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "the command would be %1 characters "
                                                          "long; the receiver takes at most %2"),
                             {std::to_string(n), std::to_string(maxLength)}));
            r.sentences.clear();
            return;
        }
    }
}

Refusal validateSetting(const SettingDef &d, std::string_view value) {
    const std::string key(d.key), given(value);
    if (value.size() > maxValueLength(d.type))
        return refusal(
                QT_TRANSLATE_NOOP("Refusal", "%1: the value is %2 characters long; at most %3"),
                {key, std::to_string(value.size()), std::to_string(maxValueLength(d.type))});
    for (char c : value) {
        if (c == '*' || c == '$' || c == '!' || static_cast<unsigned char>(c) < 0x20 ||
            static_cast<unsigned char>(c) >= 0x7F)
            return refusal(
                    QT_TRANSLATE_NOOP("Refusal", "%1: character not allowed in a value: '%2'"),
                    {key, std::string(1, c)});
    }
    switch (d.type) {
    case SettingType::Bool:
        if (value == "0" || value == "1") return {};
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected 0 or 1, got '%2'"), {key, given});
    case SettingType::Integer: {
        std::int64_t v;
        if (!parseInt(value, v))
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected an integer, got '%2'"),
                           {key, given});
        return checkRange(d, static_cast<double>(v));
    }
    case SettingType::Real: {
        double v;
        if (!parseReal(value, v))
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected a number, got '%2'"),
                           {key, given});
        return checkRange(d, v);
    }
    case SettingType::Enum: {
        std::string accepted;
        for (const auto &o : d.options) {
            if (o.value == value) return {};
            if (!accepted.empty()) accepted += ", ";
            accepted += o.value;
        }
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not one of: %3"),
                       {key, given, accepted});
    }
    case SettingType::Coordinates: {
        std::string_view rest = value;
        int n = 0;
        while (true) {
            const auto comma = rest.find(',');
            double v;
            if (!parseReal(rest.substr(0, comma), v))
                return refusal(QT_TRANSLATE_NOOP("Refusal",
                                                 "%1: expected numbers separated by ',', got '%2'"),
                               {key, given});
            ++n;
            if (comma == std::string_view::npos) break;
            rest.remove_prefix(comma + 1);
        }
        (void)n;
        return {};
    }
    case SettingType::Text:
        if (value.find(',') != std::string_view::npos)
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: ',' is not allowed in this value"),
                           {key});
        return {};
    case SettingType::List: return {};
    }
    return {};
}

} // namespace gnss
