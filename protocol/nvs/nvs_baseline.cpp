// 4.11 PNVGBRS (base-to-rover) and 4.12 PNVGBLS (ANT1-ANT2 base-line, NV08C-RTK-A only).
//
//   $PNVGBRS,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//   $PNVGBLS,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//            0 time, 1 north, 2 east, 3 vertical projection (m), 4 length (m),
//            5 course (deg from north), 6 pitch (deg from horizon), 7 mode (A D F R E N)
//   PNVGBLS before rev 1.5: no time tag (fields 1-7 only).
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

#include <span>

namespace gnss::nvs {

const MessageType Brs::kType{"PNVGBRS"};
const MessageType Bls::kType{"PNVGBLS"};

namespace {

// Metres in millimetres, angles in hundredths of a degree ($PNVGBRS,091244.60,4604.566,...,344.90,
// -0.33,R).
constexpr FieldRow<Baseline> kBaselineFields[] = {
        {&Baseline::time, "time", "time"},
        {&Baseline::north, "north", "north", {3, -kMaxMetres, kMaxMetres}},
        {&Baseline::east, "east", "east", {3, -kMaxMetres, kMaxMetres}},
        {&Baseline::vertical, "vertical", "vertical", {3, -kMaxMetres, kMaxMetres}},
        {&Baseline::length, "length", "length", {3, 0, kMaxMetres}},
        {&Baseline::course, "course", "course", {2, 0, 360}},
        {&Baseline::pitch, "pitch", "pitch", {2, -90, 90}},
        {&Baseline::mode, "mode", "mode"},
};
// Every row, or (PNVGBLS before rev 1.5, no time tag) the rows after the time.
constexpr std::span<const FieldRow<Baseline>> baselineFields(bool timed) {
    return std::span(kBaselineFields).subspan(timed ? 0 : 1);
}

template <class B> bool decodeBaseline(const Sentence &s, DecodeContext &ctx, bool timeOptional) {
    return decodeWith<B>(s, ctx, timeOptional ? 7 : 8, [&](FieldReader &r, Baseline &m) {
        readFields(r, m, baselineFields(!timeOptional || s.fieldCount() >= 8));
    });
}

// Without a time, PNVGBLS takes the form of firmware before 1.5 (no time field).
EncodeResult encodeBaseline(const Baseline &m, bool timeOptional) {
    return encodeRows(m, baselineFields(m.time || !timeOptional));
}

} // namespace

bool decodeBrs(const Sentence &s, DecodeContext &ctx) {
    return decodeBaseline<Brs>(s, ctx, false);
}

bool decodeBls(const Sentence &s, DecodeContext &ctx) {
    return decodeBaseline<Bls>(s, ctx, true);
}

void Baseline::writeJson(JsonWriter &w) const {
    writeFieldsJson(w, *this, kBaselineFields);
}

EncodeResult encodeBrs(const Brs &m) {
    return encodeBaseline(m, false);
}

EncodeResult encodeBls(const Bls &m) {
    return encodeBaseline(m, true);
}

} // namespace gnss::nvs
