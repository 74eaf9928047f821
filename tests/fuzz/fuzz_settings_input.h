#pragma once
// The input of fuzz_settings_roundtrip, shared with the seed writer (gnss_fuzz_seeds):
//
//   byte 0                      dialect: index among the dialects with a settings schema
//   then up to three records:
//     byte   setting index in the schema (wraps)
//     byte   form: bit 7 clear → bits 0-6 are a length L, and the next L bytes are the value
//                  as text; bit 7 set → the next 8 bytes derive a value from the setting's
//                  type (typedValue), bit 6 set → the key is given by its spec name alone
//                  ("MODE" for "rtk.MODE", as users type it)
#include "builtin/dialects.h"
#include "core/dialect.h"
#include "core/sentence_builder.h"
#include "core/settings_plan.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace gnss::fuzz {

inline const std::vector<const Dialect *> &dialectsWithSettings() {
    static const std::vector<const Dialect *> list = [] {
        static const DialectRegistry reg = makeBuiltinRegistry();
        std::vector<const Dialect *> out;
        for (const Dialect *d : reg.dialects())
            if (!d->settings.empty() && d->extractSettings) out.push_back(d);
        return out;
    }();
    return list;
}

// A value for `def` from 64 input bits: mostly valid, sometimes just outside what it accepts.
inline std::string typedValue(const SettingDef &def, std::uint64_t x) {
    const unsigned pick = static_cast<unsigned>(x >> 59); // 0-31
    switch (def.type) {
    case SettingType::Bool: return pick == 31 ? "2" : (x & 1 ? "1" : "0");
    case SettingType::Integer: {
        const double lo = def.min.value_or(-100000), hi = def.max.value_or(100000);
        const auto span = static_cast<std::uint64_t>(hi - lo) + 3; // one beyond either end
        return std::to_string(static_cast<long long>(lo) - 1 +
                              static_cast<long long>((x & 0xFFFFFFFFFFFULL) % span));
    }
    case SettingType::Real: {
        const double lo = def.min.value_or(-100000), hi = def.max.value_or(100000);
        const double f = static_cast<double>(x & 0xFFFFFFFF) / 4294967295.0;
        double v = lo + (hi - lo) * f;
        if (pick == 30) v = lo - 1;
        if (pick == 31) v = hi + 1;
        return formatFixed(v, static_cast<int>((x >> 32) % 10));
    }
    case SettingType::Enum:
        if (def.options.empty() || pick == 31) return "X";
        return std::string(def.options[(x & 0xFFFF) % def.options.size()].value);
    case SettingType::Coordinates: {
        // Three components: small (radians, metres) or large (ECEF metres), 4 to 10 decimals.
        std::string v;
        const bool large = (x >> 58) & 1;
        for (int k = 0; k < 3; ++k) {
            const auto bits = static_cast<std::int64_t>((x >> (k * 19)) & 0x7FFFF) - 0x40000;
            const double c = large ? static_cast<double>(bits) * 24.0 + 0.1234
                                   : static_cast<double>(bits) / 0x40000 * 1.6;
            v += (k ? "," : "") + formatFixed(c, 4 + static_cast<int>((x >> 54) % 7));
        }
        return v;
    }
    case SettingType::List: {
        static const char *kItems[] = {"GGA", "RMC", "GSV", "GSA",     "VTG", "ZDA",
                                       "GLL", "GST", "GNS", "PNVGRTK", "300", "1"};
        std::string v;
        const unsigned n = static_cast<unsigned>(x & 3);
        for (unsigned k = 0; k < n; ++k) {
            if (k) v += ";";
            v += kItems[(x >> (2 + k * 8)) % std::size(kItems)];
            if ((x >> (6 + k * 8)) & 1) v += ":" + std::to_string((x >> (7 + k * 8)) % 11);
        }
        return v;
    }
    case SettingType::Text: {
        std::string v;
        for (unsigned k = 0; k < (x & 7); ++k)
            v.push_back("ABCXYZ019 -_.:"[(x >> (3 + 4 * k)) % 14]);
        return v;
    }
    }
    return {};
}

struct SettingsCase {
    const Dialect *dialect = nullptr;
    std::vector<KeyValue> values;
};

inline SettingsCase readSettingsCase(const std::uint8_t *data, std::size_t size) {
    SettingsCase c;
    const auto &dialects = dialectsWithSettings();
    if (size == 0 || dialects.empty()) return c;
    std::size_t i = 0;
    c.dialect = dialects[data[i++] % dialects.size()];
    const auto schema = c.dialect->settings;
    while (i + 2 <= size && c.values.size() < 3) {
        const SettingDef &def = schema[data[i++] % schema.size()];
        const std::uint8_t form = data[i++];
        std::string key(def.key);
        std::string value;
        if (form & 0x80) {
            std::uint64_t x = 0;
            for (int k = 0; k < 8 && i < size; ++k) x |= std::uint64_t{data[i++]} << (8 * k);
            value = typedValue(def, x);
            if ((form & 0x40) && key.find('.') != std::string::npos)
                key = key.substr(key.rfind('.') + 1);
        } else {
            const std::size_t n = std::min<std::size_t>(form & 0x7F, size - i);
            value.assign(reinterpret_cast<const char *>(data + i), n);
            i += n;
        }
        c.values.push_back({std::move(key), std::move(value)});
    }
    return c;
}

// One record with the value as text (what the seed writer uses).
inline std::string settingsRecord(std::size_t settingIndex, std::string_view value) {
    std::string r;
    r.push_back(static_cast<char>(settingIndex));
    r.push_back(static_cast<char>(std::min<std::size_t>(value.size(), 0x7F)));
    r.append(value.substr(0, 0x7F));
    return r;
}

} // namespace gnss::fuzz
