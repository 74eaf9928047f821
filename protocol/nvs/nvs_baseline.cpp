// 4.11 PNVGBRS (base-to-rover) and 4.12 PNVGBLS (ANT1-ANT2 base-line, NV08C-RTK-A only).
//
//   $PNVGBRS,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//   $PNVGBLS,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//            0 time, 1 north, 2 east, 3 vertical projection (m), 4 length (m),
//            5 course (deg from north), 6 pitch (deg from horizon), 7 mode (A D F R E N)
//   PNVGBLS before rev 1.5: no time tag (fields 1-7 only).
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Brs::kType{"PNVGBRS"};
const MessageType Bls::kType{"PNVGBLS"};

namespace {
bool decodeBaseline(const Sentence &s, DecodeContext &ctx, Baseline &m, bool timeOptional) {
    FieldReader r(s);
    if (r.require(timeOptional ? 7 : 8)) {
        const std::size_t o = (!timeOptional || s.fieldCount() >= 8) ? 1 : 0;
        if (o) m.time = r.time(0, "time");
        m.north = r.real(o + 0, "north");
        m.east = r.real(o + 1, "east");
        m.vertical = r.real(o + 2, "vertical");
        m.length = r.real(o + 3, "length");
        m.course = r.real(o + 4, "course");
        m.pitch = r.real(o + 5, "pitch");
        m.mode = r.letter(o + 6, "mode");
    }
    return finishDecode(r, ctx, m);
}
} // namespace

bool decodeBrs(const Sentence &s, DecodeContext &ctx) {
    Brs m;
    return decodeBaseline(s, ctx, m, false);
}

bool decodeBls(const Sentence &s, DecodeContext &ctx) {
    Bls m;
    return decodeBaseline(s, ctx, m, true);
}

void Baseline::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("north", north)
            .field("east", east)
            .field("vertical", vertical)
            .field("length", length)
            .field("course", course)
            .field("pitch", pitch)
            .field("mode", mode)
            .endObject();
}

namespace {
// Metres in millimetres, angles in hundredths of a degree ($PNVGBRS,091244.60,4604.566,...,344.90,
// -0.33,R). Without a time, PNVGBLS takes the form of firmware before 1.5 (no time field).
EncodeResult encodeBaseline(const Baseline &m, bool timeOptional) {
    OutputFields f(m.type->name);
    if (m.time || !timeOptional) f.time("time", m.time);
    f.real("north", m.north, 3, -kMaxMetres, kMaxMetres)
            .real("east", m.east, 3, -kMaxMetres, kMaxMetres)
            .real("vertical", m.vertical, 3, -kMaxMetres, kMaxMetres)
            .real("length", m.length, 3, 0, kMaxMetres)
            .real("course", m.course, 2, 0, 360)
            .real("pitch", m.pitch, 2, -90, 90)
            .mode("mode", m.mode);
    return f.build();
}
} // namespace

EncodeResult encodeBrs(const Brs &m) {
    return encodeBaseline(m, false);
}

EncodeResult encodeBls(const Bls &m) {
    return encodeBaseline(m, true);
}

} // namespace gnss::nvs
