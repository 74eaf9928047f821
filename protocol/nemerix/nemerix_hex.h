#pragma once
// Packed hexadecimal fields of the PNMRX300-303 and PNMRX603 messages.
//
// Each field is described once (name, bit width, signedness, power-of-two scale, unit); the
// decoders, the encoders and the JSON output all read the same descriptor, so a scale factor
// is written down in exactly one place.
//
// Hex text of any length is accepted (the spec's widths are wrong in places, docs/spec-notes.md):
// the value must fit the field's bit width, either as the plain N-bit pattern ("FF85" for a 16-bit
// field) or already sign-extended to a wider word ("FFFFFF85"). Signed fields are then
// sign-extended from bit N-1.
#include "core/field_reader.h"
#include "core/json_writer.h"
#include "core/refusal.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gnss::nemerix {

struct HexFieldDef {
    std::string_view key;  // JSON key, snake_case
    int bits;              // width of the binary field (IS-GPS-200)
    bool isSigned;         // two's complement
    int scale;             // engineering value = raw * 2^scale
    std::string_view unit; // "s", "semicircles", "rad", "m", "m^1/2", ... ("" = pure number)
};

// Reads field i as hex of the def's width; nullopt when empty or malformed (error recorded).
std::optional<std::int64_t> readHex(FieldReader &r, std::size_t i, const HexFieldDef &def);
// raw * 2^scale.
double scaled(std::int64_t raw, const HexFieldDef &def);
// The N-bit two's complement pattern, upper case, ceil(bits/4) digits ("FF85").
std::string formatHex(std::int64_t raw, int bits);
// Whether raw fits the def's bit width and signedness.
bool fitsHex(std::int64_t raw, const HexFieldDef &def);
// Engineering value → raw (rounded); nullopt with `error` naming the field and the accepted
// range when it does not fit.
std::optional<std::int64_t> toRaw(double value, const HexFieldDef &def, std::string &error);
// The same as a refusal (translatable); `raw` is set only when it fits.
Refusal toRaw(double value, const HexFieldDef &def, std::optional<std::int64_t> &raw);
// The engineering value of raws[f] (nullopt when it is absent or f is past defs), and its
// inverse: raws[f] from an engineering value, refused (nothing set) when it does not fit; f must
// be one of defs. What value() and setValue() of the PNMRX300-303 messages do.
std::optional<double> valueOf(std::span<const HexFieldDef> defs,
                              std::span<const std::optional<std::int64_t>> raws, std::size_t f);
Refusal setValueOf(std::span<const HexFieldDef> defs, std::span<std::optional<std::int64_t>> raws,
                   std::size_t f, double value);
// Why a raw word cannot be written in the def's field (missing, or wider than its bits); empty
// when it can. Encoders check every field with it before building anything.
Refusal checkRaw(const std::optional<std::int64_t> &raw, const HexFieldDef &def);
// "," + each raw word in its field's width ("...,F3B5,FF5B"); every word already checked.
std::string hexFields(std::span<const HexFieldDef> defs,
                      std::span<const std::optional<std::int64_t>> raws);

// Writes "<key>": engineering value (an integer when scale is 0) and "<key>_raw": hex text.
void writeHexField(JsonWriter &w, const HexFieldDef &def, const std::optional<std::int64_t> &raw);
void writeHexFields(JsonWriter &w, std::span<const HexFieldDef> defs,
                    std::span<const std::optional<std::int64_t>> raws);

} // namespace gnss::nemerix
