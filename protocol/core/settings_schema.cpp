#include "settings_schema.h"

#include "field_parse.h"
#include "sentence_builder.h"

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
    if (!d.unit.empty() && !r.empty()) r += " " + std::string(d.unit);
    return r;
}

bool checkRange(const SettingDef &d, double v, std::string &err) {
    if ((d.min && v < *d.min) || (d.max && v > *d.max)) {
        err = std::string(d.key) + ": " + formatFixed(v, v == std::floor(v) ? 0 : 6) +
              " is out of range; accepted: " + rangeText(d);
        return false;
    }
    return true;
}

} // namespace

std::string validateSetting(const SettingDef &d, std::string_view value) {
    std::string err;
    for (char c : value) {
        if (c == '*' || c == '$' || c == '!' || static_cast<unsigned char>(c) < 0x20 ||
            static_cast<unsigned char>(c) >= 0x7F)
            return std::string(d.key) + ": character not allowed in a value: '" + c + "'";
    }
    switch (d.type) {
    case SettingType::Bool:
        if (value == "0" || value == "1") return {};
        return std::string(d.key) + ": expected 0 or 1, got '" + std::string(value) + "'";
    case SettingType::Integer: {
        std::int64_t v;
        if (!parseInt(value, v))
            return std::string(d.key) + ": expected an integer, got '" + std::string(value) + "'";
        checkRange(d, static_cast<double>(v), err);
        return err;
    }
    case SettingType::Real: {
        double v;
        if (!parseReal(value, v))
            return std::string(d.key) + ": expected a number, got '" + std::string(value) + "'";
        checkRange(d, v, err);
        return err;
    }
    case SettingType::Enum: {
        std::string accepted;
        for (const auto &o : d.options) {
            if (o.value == value) return {};
            if (!accepted.empty()) accepted += ", ";
            accepted += o.value;
        }
        return std::string(d.key) + ": '" + std::string(value) + "' is not one of: " + accepted;
    }
    case SettingType::Coordinates: {
        std::string_view rest = value;
        int n = 0;
        while (true) {
            const auto comma = rest.find(',');
            double v;
            if (!parseReal(rest.substr(0, comma), v))
                return std::string(d.key) + ": expected numbers separated by ',', got '" +
                       std::string(value) + "'";
            ++n;
            if (comma == std::string_view::npos) break;
            rest.remove_prefix(comma + 1);
        }
        (void)n;
        return {};
    }
    case SettingType::Text:
        if (value.find(',') != std::string_view::npos)
            return std::string(d.key) + ": ',' is not allowed in this value";
        return {};
    case SettingType::List: return {};
    }
    return {};
}

} // namespace gnss
