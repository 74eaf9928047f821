// PNMRX106: map datum.
//
//   $PNMRX106,c,ddd,dx,dy,dz,iflat,majora*hh
//             0 correction mode (1 = EGM96 geoid correction, meant for datum 216),
//             1 datum (0-218 internal table, 500 user defined), 2-4 dx, dy, dz (m, ±9999),
//             5 (1/f - 290) * 1e6 in [6000000, 12000000], 6 (a - 6370000) * 1000 in
//             [6000000, 9000000]
//   $PNMRX106, 1, 216,*46                                           WGS 84
//   $PNMRX106, 0,500, -2000,-2000,-2000, 8257224, 8137000*69        user datum (spec prints *00)
#include "core/decode_with.h"
#include "core/field_table.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"

#include <cmath>

namespace gnss::nemerix {

const MessageType DatumSetting::kType{"PNMRX106"};

std::optional<double> DatumSetting::inverseFlattening() const {
    if (!iflatRaw) return std::nullopt;
    return 290.0 + static_cast<double>(*iflatRaw) / 1e6;
}
std::optional<double> DatumSetting::semiMajorAxis() const {
    if (!majorARaw) return std::nullopt;
    return 6370000.0 + static_cast<double>(*majorARaw) / 1000.0;
}

namespace {
const FieldRow<DatumSetting> kFields[] = {
        {&DatumSetting::correction, "correction mode", "correction"},
        {&DatumSetting::datum, "map datum", "datum"},
        {&DatumSetting::dx, "dx", "dx"},
        {&DatumSetting::dy, "dy", "dy"},
        {&DatumSetting::dz, "dz", "dz"},
        {&DatumSetting::iflatRaw, "inverse flatness", "iflat_raw"},
        {&DatumSetting::majorARaw, "semi-major axis", "major_axis_raw"},
};

// The ranges the rows' values must lie in.
void checkDatum(FieldReader &r, const DatumSetting &m) {
    if (m.correction && (*m.correction < 0 || *m.correction > 1))
        r.fail(0, "correction mode", QT_TRANSLATE_NOOP("Refusal", "not 0 or 1"));
    if (m.datum && !((*m.datum >= 0 && *m.datum <= 218) || *m.datum == 500))
        r.fail(1, "map datum", QT_TRANSLATE_NOOP("Refusal", "not 0..218 or 500"));
    const std::optional<int> *offsets[] = {&m.dx, &m.dy, &m.dz};
    for (std::size_t i = 0; i < 3; ++i)
        if (*offsets[i] && std::abs(**offsets[i]) > 9999)
            r.fail(2 + i, "offset", QT_TRANSLATE_NOOP("Refusal", "out of range -9999..9999"));
    if (m.iflatRaw && (*m.iflatRaw < 6000000 || *m.iflatRaw > 12000000))
        r.fail(5, "inverse flatness",
               QT_TRANSLATE_NOOP("Refusal", "out of range 6000000..12000000"));
    if (m.majorARaw && (*m.majorARaw < 6000000 || *m.majorARaw > 9000000))
        r.fail(6, "semi-major axis", QT_TRANSLATE_NOOP("Refusal", "out of range 6000000..9000000"));
}
} // namespace

bool decodeDatum(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<DatumSetting>(s, ctx, 0, [](FieldReader &r, DatumSetting &m) {
        readFields(r, m, kFields);
        checkDatum(r, m);
    });
}

void DatumSetting::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("correction", correction)
            .field("datum", datum)
            .field("user_defined", datum ? *datum == 500 : false)
            .field("dx", dx)
            .field("dy", dy)
            .field("dz", dz)
            .field("iflat_raw", iflatRaw)
            .field("inverse_flattening", inverseFlattening())
            .field("major_axis_raw", majorARaw)
            .field("semi_major_axis_m", semiMajorAxis())
            .endObject();
}

EncodeResult encodeDatum(const DatumParams &p, std::string_view prefix) {
    EncodeResult r;
    if (p.correction < 0 || p.correction > 1) {
        r.error = "correction: " + std::to_string(p.correction) +
                  " is out of range; accepted: 0 (none) or 1 (EGM96)";
        return r;
    }
    if (!((p.datum >= 0 && p.datum <= 218) || p.datum == 500)) {
        r.error = "datum: " + std::to_string(p.datum) +
                  " is out of range; accepted: 0..218 (internal table) or 500 (user defined)";
        return r;
    }
    if (p.datum != 500)
        return buildCommand(
                "106", "," + std::to_string(p.correction) + "," + std::to_string(p.datum) + ",",
                prefix);
    if (!p.dx || !p.dy || !p.dz || !p.inverseFlattening || !p.semiMajorAxis) {
        r.error = "datum 500 (user defined) needs dx, dy, dz, inverse flattening and semi-major "
                  "axis";
        return r;
    }
    for (int v : {*p.dx, *p.dy, *p.dz}) {
        if (v < -9999 || v > 9999) {
            r.error = "datum offset: " + std::to_string(v) +
                      " is out of range; accepted: -9999..9999 m";
            return r;
        }
    }
    const double iflat = *p.inverseFlattening, a = *p.semiMajorAxis;
    if (!(iflat >= 296.0 && iflat <= 302.0)) {
        r.error = "inverse flattening: " + formatFixed(iflat, 6) +
                  " is out of range; accepted: 296..302";
        return r;
    }
    if (!(a >= 6376000.0 && a <= 6379000.0)) {
        r.error = "semi-major axis: " + formatFixed(a, 3) +
                  " is out of range; accepted: 6376000..6379000 m";
        return r;
    }
    const long long iflatRaw = std::llround((iflat - 290.0) * 1e6);
    const long long aRaw = std::llround((a - 6370000.0) * 1000.0);
    return buildCommand("106",
                        "," + std::to_string(p.correction) + ",500," + std::to_string(*p.dx) + "," +
                                std::to_string(*p.dy) + "," + std::to_string(*p.dz) + "," +
                                std::to_string(iflatRaw) + "," + std::to_string(aRaw),
                        prefix);
}

} // namespace gnss::nemerix
