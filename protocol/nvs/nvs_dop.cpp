// 4.22 PNVGDOP: dilutions of precision of the calculated position. (The spec's field table
// names the address PNVGSDH, a copy-paste typo: the example shows PNVGDOP. docs/spec-notes.md.)
//
//   $PNVGDOP,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//            0 time, 1 GDOP, 2 PDOP, 3 HDOP, 4 VDOP, 5 TDOP, 6 nDOP, 7 eDOP, 8 mode
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Dop::kType{"PNVGDOP"};

bool decodeDop(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Dop m;
    if (r.require(9)) {
        m.time = r.time(0, "time");
        m.gdop = r.real(1, "GDOP");
        m.pdop = r.real(2, "PDOP");
        m.hdop = r.real(3, "HDOP");
        m.vdop = r.real(4, "VDOP");
        m.tdop = r.real(5, "TDOP");
        m.ndop = r.real(6, "nDOP");
        m.edop = r.real(7, "eDOP");
        m.mode = r.letter(8, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Dop::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("gdop", gdop)
            .field("pdop", pdop)
            .field("hdop", hdop)
            .field("vdop", vdop)
            .field("tdop", tdop)
            .field("ndop", ndop)
            .field("edop", edop)
            .field("mode", mode)
            .endObject();
}

// Each DOP with two decimals.
EncodeResult encodeDop(const Dop &m) {
    OutputFields f(Dop::kType.name);
    f.time("time", m.time)
            .real("GDOP", m.gdop, 2, 0, kMaxDop)
            .real("PDOP", m.pdop, 2, 0, kMaxDop)
            .real("HDOP", m.hdop, 2, 0, kMaxDop)
            .real("VDOP", m.vdop, 2, 0, kMaxDop)
            .real("TDOP", m.tdop, 2, 0, kMaxDop)
            .real("nDOP", m.ndop, 2, 0, kMaxDop)
            .real("eDOP", m.edop, 2, 0, kMaxDop)
            .mode("mode", m.mode);
    return f.build();
}

} // namespace gnss::nvs
