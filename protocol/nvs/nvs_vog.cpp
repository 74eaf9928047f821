// 4.13 PNVGVOG: velocity over ground.
//
//   $PNVGVOG,hhmmss.ss,x.x,x.x,x.x,a*hh
//            0 time, 1 north, 2 east, 3 vertical velocity (m/s), 4 mode (A D F R E N)
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Vog::kType{"PNVGVOG"};

bool decodeVog(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Vog m;
    if (r.require(5)) {
        m.time = r.time(0, "time");
        m.velNorth = r.real(1, "north velocity");
        m.velEast = r.real(2, "east velocity");
        m.velUp = r.real(3, "vertical velocity");
        m.mode = r.letter(4, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Vog::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("vel_north", velNorth)
            .field("vel_east", velEast)
            .field("vel_up", velUp)
            .field("mode", mode)
            .endObject();
}

// Velocities in mm/s.
EncodeResult encodeVog(const Vog &m) {
    OutputFields f(Vog::kType.name);
    f.time("time", m.time)
            .real("north velocity", m.velNorth, 3, -kMaxSpeed, kMaxSpeed)
            .real("east velocity", m.velEast, 3, -kMaxSpeed, kMaxSpeed)
            .real("vertical velocity", m.velUp, 3, -kMaxSpeed, kMaxSpeed)
            .mode("mode", m.mode);
    return f.build();
}

} // namespace gnss::nvs
