// 4.19 PNVGSDP, 4.20 PNVGSDV, 4.21 PNVGSDH: standard deviation (rms) of position, velocity and
// heading, with the mode indicator (A D F R E N).
//
//   $PNVGSDP,hhmmss.ss,x.x,x.x,x.x,a*hh   0 time, 1 latitude, 2 longitude, 3 height (m), 4 mode
//   $PNVGSDV,hhmmss.ss,x.x,x.x,x.x,a*hh   0 time, 1 north, 2 east, 3 vertical (m/s), 4 mode
//   $PNVGSDH,hhmmss.ss,x.x,a*hh           0 time, 1 heading (deg), 2 mode
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Sdp::kType{"PNVGSDP"};
const MessageType Sdv::kType{"PNVGSDV"};
const MessageType Sdh::kType{"PNVGSDH"};

bool decodeSdp(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Sdp m;
    if (r.require(5)) {
        m.time = r.time(0, "time");
        m.sdLat = r.real(1, "latitude deviation");
        m.sdLon = r.real(2, "longitude deviation");
        m.sdHeight = r.real(3, "height deviation");
        m.mode = r.letter(4, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Sdp::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("sd_lat", sdLat)
            .field("sd_lon", sdLon)
            .field("sd_height", sdHeight)
            .field("mode", mode)
            .endObject();
}

bool decodeSdv(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Sdv m;
    if (r.require(5)) {
        m.time = r.time(0, "time");
        m.sdVelNorth = r.real(1, "north velocity deviation");
        m.sdVelEast = r.real(2, "east velocity deviation");
        m.sdVelUp = r.real(3, "vertical velocity deviation");
        m.mode = r.letter(4, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Sdv::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("sd_vel_north", sdVelNorth)
            .field("sd_vel_east", sdVelEast)
            .field("sd_vel_up", sdVelUp)
            .field("mode", mode)
            .endObject();
}

bool decodeSdh(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Sdh m;
    if (r.require(3)) {
        m.time = r.time(0, "time");
        m.sdHeading = r.real(1, "heading deviation");
        m.mode = r.letter(2, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Sdh::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("sd_heading", sdHeading)
            .field("mode", mode)
            .endObject();
}

// Deviations in millimetres, mm/s and thousandths of a degree.
EncodeResult encodeSdp(const Sdp &m) {
    OutputFields f(Sdp::kType.name);
    f.time("time", m.time)
            .real("latitude deviation", m.sdLat, 3, 0, kMaxMetres)
            .real("longitude deviation", m.sdLon, 3, 0, kMaxMetres)
            .real("height deviation", m.sdHeight, 3, 0, kMaxMetres)
            .mode("mode", m.mode);
    return f.build();
}

EncodeResult encodeSdv(const Sdv &m) {
    OutputFields f(Sdv::kType.name);
    f.time("time", m.time)
            .real("north velocity deviation", m.sdVelNorth, 3, 0, kMaxSpeed)
            .real("east velocity deviation", m.sdVelEast, 3, 0, kMaxSpeed)
            .real("vertical velocity deviation", m.sdVelUp, 3, 0, kMaxSpeed)
            .mode("mode", m.mode);
    return f.build();
}

EncodeResult encodeSdh(const Sdh &m) {
    OutputFields f(Sdh::kType.name);
    f.time("time", m.time).real("heading deviation", m.sdHeading, 3, 0, 360).mode("mode", m.mode);
    return f.build();
}

} // namespace gnss::nvs
