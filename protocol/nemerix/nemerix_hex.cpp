#include "nemerix/nemerix_hex.h"

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

Refusal toRaw(double value, const HexFieldDef &def, std::optional<std::int64_t> &raw) {
    raw.reset();
    if (!std::isfinite(value))
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected a number, got '%2'"),
                       {std::string(def.key), number(value)});
    const double r = std::nearbyint(std::ldexp(value, -def.scale));
    if (r < static_cast<double>(minRaw(def)) || r > static_cast<double>(maxRaw(def))) {
        std::vector<std::string> args{std::string(def.key), number(value),
                                      number(scaled(minRaw(def), def)) + ".." +
                                              number(scaled(maxRaw(def), def))};
        if (def.unit.empty())
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                           std::move(args));
        args.emplace_back(def.unit);
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3 %4"),
                       std::move(args));
    }
    raw = static_cast<std::int64_t>(r);
    return {};
}

std::optional<std::int64_t> toRaw(double value, const HexFieldDef &def, std::string &error) {
    std::optional<std::int64_t> raw;
    if (Refusal why = toRaw(value, def, raw); !why.empty()) error = why.text;
    return raw;
}

std::optional<double> valueOf(std::span<const HexFieldDef> defs,
                              std::span<const std::optional<std::int64_t>> raws, std::size_t f) {
    if (f >= defs.size() || !raws[f]) return std::nullopt;
    return scaled(*raws[f], defs[f]);
}

Refusal setValueOf(std::span<const HexFieldDef> defs, std::span<std::optional<std::int64_t>> raws,
                   std::size_t f, double value) {
    std::optional<std::int64_t> r;
    Refusal why = toRaw(value, defs[f], r);
    if (why.empty()) raws[f] = r;
    return why;
}

Refusal checkRaw(const std::optional<std::int64_t> &raw, const HexFieldDef &def) {
    if (!raw) return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: missing"), {std::string(def.key)});
    if (fitsHex(*raw, def)) return {};
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                   {std::string(def.key), std::to_string(*raw),
                    std::to_string(minRaw(def)) + ".." + std::to_string(maxRaw(def))});
}

std::string hexFields(std::span<const HexFieldDef> defs,
                      std::span<const std::optional<std::int64_t>> raws) {
    std::string s;
    for (std::size_t i = 0; i < defs.size() && i < raws.size(); ++i)
        s += "," + (raws[i] ? formatHex(*raws[i], defs[i].bits) : std::string());
    return s;
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
