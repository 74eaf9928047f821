#include "nemerix_hex.h"

#include "core/field_parse.h"
#include "core/sentence_builder.h"

#include <cmath>

namespace gnss::nemerix {

std::optional<std::int64_t> readHex(FieldReader &r, std::size_t i, const HexFieldDef &def) {
    const auto text = r.text(i);
    if (text.empty()) return std::nullopt;
    std::uint64_t v;
    if (!parseHex(text, v)) {
        r.fail(i, def.key.data(), QT_TRANSLATE_NOOP("Refusal", "not hexadecimal"));
        return std::nullopt;
    }
    const int bits = def.bits;
    const std::uint64_t mask = bits >= 64 ? ~0ULL : ((1ULL << bits) - 1);
    const std::uint64_t high = v & ~mask;
    const bool signBit = (v >> (bits - 1)) & 1;
    // Accept the plain N-bit pattern, or a value already sign-extended to a wider word.
    const bool plain = high == 0;
    const bool extended =
            def.isSigned && signBit && text.size() * 4 > static_cast<std::size_t>(bits) &&
            high == (~mask & ((text.size() >= 16) ? ~0ULL : ((1ULL << (text.size() * 4)) - 1)));
    if (!plain && !extended) {
        r.fail(i, def.key.data(),
               QT_TRANSLATE_NOOP("Refusal", "does not fit the field's bit width"));
        return std::nullopt;
    }
    std::uint64_t low = v & mask;
    if (def.isSigned && signBit && bits < 64) low |= ~mask; // sign-extend from bit N-1
    return static_cast<std::int64_t>(low);
}

double scaled(std::int64_t raw, const HexFieldDef &def) {
    return std::ldexp(static_cast<double>(raw), def.scale);
}

std::string formatHex(std::int64_t raw, int bits) {
    static const char hex[] = "0123456789ABCDEF";
    const int digits = (bits + 3) / 4;
    const std::uint64_t mask = bits >= 64 ? ~0ULL : ((1ULL << bits) - 1);
    std::uint64_t v = static_cast<std::uint64_t>(raw) & mask;
    std::string s(static_cast<std::size_t>(digits), '0');
    for (int d = digits - 1; d >= 0; --d) {
        s[static_cast<std::size_t>(d)] = hex[v & 15];
        v >>= 4;
    }
    return s;
}

namespace {
std::int64_t minRaw(const HexFieldDef &d) {
    return d.isSigned ? -(1LL << (d.bits - 1)) : 0;
}
std::int64_t maxRaw(const HexFieldDef &d) {
    return d.isSigned ? (1LL << (d.bits - 1)) - 1 : (1LL << d.bits) - 1;
}
std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return buf;
}
} // namespace

bool fitsHex(std::int64_t raw, const HexFieldDef &def) {
    return raw >= minRaw(def) && raw <= maxRaw(def);
}

std::optional<std::int64_t> toRaw(double value, const HexFieldDef &def, std::string &error) {
    if (!std::isfinite(value)) {
        error = std::string(def.key) + ": not a finite number";
        return std::nullopt;
    }
    const double r = std::nearbyint(std::ldexp(value, -def.scale));
    if (r < static_cast<double>(minRaw(def)) || r > static_cast<double>(maxRaw(def))) {
        error = std::string(def.key) + ": " + number(value) +
                " is out of range; accepted: " + number(scaled(minRaw(def), def)) + ".." +
                number(scaled(maxRaw(def), def));
        if (!def.unit.empty()) error += " " + std::string(def.unit);
        return std::nullopt;
    }
    return static_cast<std::int64_t>(r);
}

void writeHexField(JsonWriter &w, const HexFieldDef &def, const std::optional<std::int64_t> &raw) {
    w.key(def.key);
    if (!raw)
        w.null();
    else if (def.scale == 0)
        w.value(*raw);
    else
        w.value(scaled(*raw, def));
    std::string rawKey(def.key);
    rawKey += "_raw";
    w.key(rawKey);
    if (raw)
        w.value(formatHex(*raw, def.bits));
    else
        w.null();
}

void writeHexFields(JsonWriter &w, std::span<const HexFieldDef> defs,
                    std::span<const std::optional<std::int64_t>> raws) {
    for (std::size_t i = 0; i < defs.size() && i < raws.size(); ++i)
        writeHexField(w, defs[i], raws[i]);
}

} // namespace gnss::nemerix
