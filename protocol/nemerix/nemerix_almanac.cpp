// PNMRX300: almanac of one satellite (receiver output, and upload to the receiver).
//
//   $PNMRX300,sv,e,hh,ta,ii,od,sqa,om0,w,mean,m0,af0,af1*hh      fields in hex after sv
//
// Field widths, signs and scales follow IS-GPS-200 (20.3.3.5.1.2, table 20-VI), which is where
// the spec's table comes from; where the table disagrees, IS-GPS-200 wins (docs/spec-notes.md):
//   - e is a 16-bit UNSIGNED value (table: "signed"), scale 2^-21.
//   - toa: the table's note says "Week Number"; the column is toa, 8 bits, scale 2^12 s.
//   - i is delta-i relative to i0 = 0.30 semi-circles, 16-bit signed, 2^-19 semi-circles.
//   - af1 scale is 2^-38 s/s (table: 2^-68).
//   - The table lists both "Mean" and "Mean anomaly" (24-bit signed, 2^-23): the almanac has one
//     mean anomaly. A sentence with 12 hex fields is read per the table (the "Mean" field kept
//     as-is); one with 11 hex fields is read without it. Encoding writes the table's 12 fields,
//     "Mean" = M0 unless set.
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

namespace gnss::nemerix {

const MessageType Almanac::kType{"PNMRX300"};

namespace {
constexpr HexFieldDef kAlmanacFields[] = {
        {"e", 16, false, -21, ""},
        {"health", 8, false, 0, ""},
        {"toa", 8, false, 12, "s"},
        {"delta_i", 16, true, -19, "semicircles"},
        {"omega_dot", 16, true, -38, "semicircles/s"},
        {"sqrt_a", 24, false, -11, "m^1/2"},
        {"omega0", 24, true, -23, "semicircles"},
        {"perigee", 24, true, -23, "semicircles"},
        {"mean", 24, true, -23, "semicircles"},
        {"m0", 24, true, -23, "semicircles"},
        {"af0", 11, true, -20, "s"},
        {"af1", 11, true, -38, "s/s"},
};
static_assert(std::size(kAlmanacFields) == Almanac::kFieldCount);
} // namespace

std::span<const HexFieldDef> Almanac::fields() {
    return kAlmanacFields;
}

bool decodeAlmanac(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Almanac m;
    const std::size_t n = usedFields(r);
    if (n != 1 + Almanac::kFieldCount && n != Almanac::kFieldCount)
        r.failSentence(refusal(QT_TRANSLATE_NOOP("Refusal", "expected 12 (or 11) hex fields "
                                                            "after the SV id, got %1"),
                               {std::to_string(n > 0 ? n - 1 : 0)}));
    const auto sv = r.integer(0, "SV id");
    if (sv && (*sv < 1 || *sv > 32))
        r.fail(0, "SV id", QT_TRANSLATE_NOOP("Refusal", "out of range 1..32"));
    if (!sv && r.ok()) r.fail(0, "SV id", QT_TRANSLATE_NOOP("Refusal", "missing"));
    if (sv) m.sv = *sv;
    const bool withMean = n == 1 + Almanac::kFieldCount;
    std::size_t i = 1;
    for (int f = 0; f < Almanac::kFieldCount && r.ok(); ++f) {
        if (f == Almanac::Mean && !withMean) continue;
        m.raw[f] = readHex(r, i++, kAlmanacFields[f]);
    }
    return finishDecode(r, ctx, m);
}

void Almanac::writeJson(JsonWriter &w) const {
    w.beginObject().field("sv", sv);
    writeHexFields(w, kAlmanacFields, raw);
    w.key("inclination");
    if (raw[DeltaI])
        w.value(0.30 + *value(DeltaI)); // i0 = 0.30 semi-circles (IS-GPS-200)
    else
        w.null();
    w.endObject();
}

EncodeResult encodeAlmanac(const Almanac &a, std::string_view prefix) {
    EncodeResult r;
    if (a.sv < 1 || a.sv > 32) {
        r.error = "sv: " + std::to_string(a.sv) + " is out of range; accepted: 1..32";
        return r;
    }
    std::string fields = "," + std::to_string(a.sv);
    for (int f = 0; f < Almanac::kFieldCount; ++f) {
        std::optional<std::int64_t> v = a.raw[f];
        if (f == Almanac::Mean && !v) v = a.raw[Almanac::M0];
        if (!v) {
            r.error = std::string(kAlmanacFields[f].key) + ": missing";
            return r;
        }
        if (!fitsHex(*v, kAlmanacFields[f])) {
            r.error = std::string(kAlmanacFields[f].key) + ": raw value " + std::to_string(*v) +
                      " does not fit " + std::to_string(kAlmanacFields[f].bits) +
                      (kAlmanacFields[f].isSigned ? " signed" : " unsigned") + " bits";
            return r;
        }
        fields += "," + formatHex(*v, kAlmanacFields[f].bits);
    }
    return buildCommand("300", fields, prefix);
}

} // namespace gnss::nemerix
