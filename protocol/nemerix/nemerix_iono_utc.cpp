// PNMRX302 (ionospheric correction), PNMRX303 (GPS-UTC parameters), PNMRX304 (health).
//
//   $PNMRX302,sv,a0,a1,a2,a3,b0,b1,b2,b3*hh   Klobuchar coefficients, 8-bit signed hex each
//     (IS-GPS-200 20.3.3.5.1.7: a0 2^-30 s, a1 2^-27 s/semicircle, a2 2^-24 s/semicircle^2,
//      a3 2^-24 s/semicircle^3, b0 2^11 s, b1 2^14, b2 2^16, b3 2^16; the table agrees). A
//     sentence without the leading SV id (8 fields) is read too.
//
//   $PNMRX303,sv,a0,a1,dtls,tot,wnt,wnlsf,dn,dtlsf,blocks,offset*hh
//     The table prints width 2 for every field and gives no scales; IS-GPS-200 20.3.3.5.1.6
//     does: A0 32-bit signed 2^-30 s, A1 24-bit signed 2^-50 s/s, dtLS 8-bit signed s, tot
//     8 bits 2^12 s, WNt 8 bits, WNLSF 8 bits, DN 8 bits (days), dtLSF 8-bit signed s. The last
//     two (number of 20-year blocks, local time offset) are not GPS data: kept as sent. The
//     satellite id is printed with width 8 in the table: read as a decimal number.
//
//   $PNMRX304,code,code,...*hh   the fields are "TBD" in the spec: kept as sent.
//
// The encoders write what the receiver sends: each hex word in its field's width (IS-GPS-200),
// the SV id in decimal, the health codes as given.
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

namespace gnss::nemerix {

const MessageType Ionosphere::kType{"PNMRX302"};
const MessageType UtcParameters::kType{"PNMRX303"};
const MessageType ConstellationHealth::kType{"PNMRX304"};

namespace {
constexpr HexFieldDef kIono[] = {
        {"alpha0", 8, true, -30, "s"},
        {"alpha1", 8, true, -27, "s/semicircle"},
        {"alpha2", 8, true, -24, "s/semicircle^2"},
        {"alpha3", 8, true, -24, "s/semicircle^3"},
        {"beta0", 8, true, 11, "s"},
        {"beta1", 8, true, 14, "s/semicircle"},
        {"beta2", 8, true, 16, "s/semicircle^2"},
        {"beta3", 8, true, 16, "s/semicircle^3"},
};
constexpr HexFieldDef kUtc[] = {
        {"a0", 32, true, -30, "s"},       {"a1", 24, true, -50, "s/s"},
        {"dt_ls", 8, true, 0, "s"},       {"tot", 8, false, 12, "s"},
        {"wn_t", 8, false, 0, "weeks"},   {"wn_lsf", 8, false, 0, "weeks"},
        {"dn", 8, false, 0, "days"},      {"dt_lsf", 8, true, 0, "s"},
        {"num_blocks", 32, false, 0, ""}, {"time_offset", 32, false, 0, ""},
};
static_assert(std::size(kUtc) == UtcParameters::kFieldCount);
} // namespace

std::span<const HexFieldDef> Ionosphere::fields() {
    return kIono;
}
std::span<const HexFieldDef> UtcParameters::fields() {
    return kUtc;
}

namespace {
Refusal badSv(int sv) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                   {"sv", std::to_string(sv), "1..32"});
}
} // namespace

bool decodeIonosphere(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Ionosphere m;
    const std::size_t n = usedFields(r);
    std::size_t first = 0;
    if (n == 9) {
        m.sv = r.integer(0, "SV id");
        first = 1;
    } else if (n != 8) {
        r.failSentence(refusal(QT_TRANSLATE_NOOP("Refusal", "expected the SV id and 8 hex "
                                                            "coefficients, got %1 fields"),
                               {std::to_string(n)}));
    }
    for (std::size_t f = 0; f < 8 && r.ok(); ++f) m.raw[f] = readHex(r, first + f, kIono[f]);
    return finishDecode(r, ctx, m);
}

bool decodeUtc(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    UtcParameters m;
    const std::size_t n = usedFields(r);
    if (n < 9)
        r.failSentence(std::string(
                QT_TRANSLATE_NOOP("Refusal", "expected the SV id and at least 8 hex fields")));
    m.sv = r.integer(0, "SV id");
    for (std::size_t f = 0; f < UtcParameters::kFieldCount && r.ok(); ++f)
        m.raw[f] = readHex(r, 1 + f, kUtc[f]);
    return finishDecode(r, ctx, m);
}

bool decodeHealth(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    ConstellationHealth m;
    readTexts(r, m.codes, m.count);
    return finishDecode(r, ctx, m);
}

EncodeResult encodeIonosphere(const Ionosphere &m, std::string_view prefix) {
    EncodeResult r;
    if (m.sv && (*m.sv < 1 || *m.sv > 32)) r.refuse(badSv(*m.sv));
    for (std::size_t f = 0; f < std::size(kIono) && r.ok(); ++f)
        if (Refusal why = checkRaw(m.raw[f], kIono[f]); !why.empty()) r.refuse(std::move(why));
    if (!r.ok()) return r;
    // Without an SV id: the 8-field form the decoder also reads.
    return buildCommand("302", (m.sv ? "," + std::to_string(*m.sv) : "") + hexFields(kIono, m.raw),
                        prefix);
}

EncodeResult encodeUtc(const UtcParameters &m, std::string_view prefix) {
    EncodeResult r;
    if (m.sv && (*m.sv < 1 || *m.sv > 32)) r.refuse(badSv(*m.sv));
    // A0 to dtLSF are the GPS data and required; the two words after them are optional.
    std::size_t used = UtcParameters::kFieldCount;
    while (used > UtcParameters::NumBlocks && !m.raw[used - 1]) --used;
    for (std::size_t f = 0; f < used && r.ok(); ++f) {
        if (f >= UtcParameters::NumBlocks && !m.raw[f]) continue; // an empty field
        if (Refusal why = checkRaw(m.raw[f], kUtc[f]); !why.empty()) r.refuse(std::move(why));
    }
    if (!r.ok()) return r;
    return buildCommand("303",
                        "," + (m.sv ? std::to_string(*m.sv) : std::string()) +
                                hexFields(std::span(kUtc).first(used), m.raw),
                        prefix);
}

EncodeResult encodeHealth(const ConstellationHealth &m, std::string_view prefix) {
    EncodeResult r;
    if (m.count > ConstellationHealth::kMax) {
        r.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                         {"health codes", std::to_string(m.count),
                          "0.." + std::to_string(ConstellationHealth::kMax)}));
        return r;
    }
    std::string fields;
    for (std::size_t i = 0; i < m.count; ++i) {
        if (Refusal why = checkFieldText("health code", m.codes[i]); !why.empty()) {
            r.refuse(std::move(why));
            return r;
        }
        fields += ",";
        fields += m.codes[i];
    }
    return buildCommand("304", fields, prefix);
}

void ConstellationHealth::writeJson(JsonWriter &w) const {
    w.beginObject().field("count", count).key("codes").beginArray();
    for (std::size_t i = 0; i < count; ++i) w.value(codes[i]);
    w.endArray().endObject();
}

} // namespace gnss::nemerix
