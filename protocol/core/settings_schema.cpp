#include "core/settings_schema.h"

#include "core/field_parse.h"
#include "core/sentence_builder.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

namespace {

char lowerAscii(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

bool sameText(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lowerAscii(a[i]) != lowerAscii(b[i])) return false;
    return true;
}

// The spec's own name of a row: its key after the last '.'.
std::string_view ownName(std::string_view key) {
    const auto dot = key.rfind('.');
    return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

// The rows `key` answers to: the exact key; else the key in another case; else the rows whose
// own name (or a dotted tail of their key: "COM1.baud") it is, as written, else in any case.
std::vector<const SettingDef *> rowsNamed(std::span<const SettingDef> schema,
                                          std::string_view key) {
    std::vector<const SettingDef *> rows;
    for (const auto &d : schema)
        if (d.key == key) return {&d};
    for (const auto &d : schema)
        if (sameText(d.key, key)) return {&d};
    // The name as written first ("MODE" is rtk.MODE, though pps.mode is "mode"), then in any case.
    for (const bool anyCase : {false, true}) {
        for (const auto &d : schema) {
            if (d.key.size() <= key.size() || d.key[d.key.size() - key.size() - 1] != '.') continue;
            const std::string_view tail = d.key.substr(d.key.size() - key.size());
            if (anyCase ? sameText(tail, key) : tail == key) rows.push_back(&d);
        }
        if (!rows.empty()) break;
    }
    return rows;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1,
                               diagonal + (lowerAscii(a[i - 1]) == lowerAscii(b[j - 1]) ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

} // namespace

const SettingDef *findSetting(std::span<const SettingDef> schema, std::string_view key) {
    const auto rows = rowsNamed(schema, key);
    return rows.size() == 1 ? rows.front() : nullptr; // several: ambiguous
}

std::string SettingKeyHint::list() const {
    std::string out;
    for (std::size_t i = 0; i < keys.size(); ++i)
        out += (i == 0 ? "" : i + 1 == keys.size() ? " or " : ", ") + keys[i];
    return out;
}

SettingKeyHint settingKeyHint(std::span<const SettingDef> schema, std::string_view key) {
    SettingKeyHint hint;
    const auto rows = rowsNamed(schema, key);
    if (rows.size() == 1) return hint;
    if (rows.size() > 1) {
        hint.ambiguous = true;
        for (const SettingDef *d : rows) hint.keys.emplace_back(d->key);
        return hint;
    }
    // The nearest keys, by the edit distance to the whole key or to its own name.
    std::vector<std::pair<std::size_t, std::string_view>> near;
    for (const auto &d : schema) {
        const std::size_t n = std::min(editDistance(key, d.key), editDistance(key, ownName(d.key)));
        if (n <= std::max<std::size_t>(2, key.size() / 3)) near.emplace_back(n, d.key);
    }
    std::stable_sort(near.begin(), near.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    for (std::size_t i = 0; i < near.size() && i < 3; ++i) hint.keys.emplace_back(near[i].second);
    return hint;
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
