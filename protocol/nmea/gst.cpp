// GST: GNSS pseudorange error statistics (NMEA 0183 4.11 §6.3).
//
//   $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x*hh
//          0 time, 1 RMS of range residuals, 2 error ellipse semi-major (m), 3 semi-minor (m),
//          4 orientation (deg), 5 sd latitude (m), 6 sd longitude (m), 7 sd altitude (m)
#include "nmea_messages.h"

namespace gnss::nmea {

const MessageType Gst::kType{"GST"};

bool decodeGst(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Gst m;
    if (r.require(8)) {
        m.time = r.time(0, "time");
        m.rms = r.real(1, "rms");
        m.sdMajor = r.real(2, "semi-major");
        m.sdMinor = r.real(3, "semi-minor");
        m.orientation = r.real(4, "orientation");
        m.sdLat = r.real(5, "sd latitude");
        m.sdLon = r.real(6, "sd longitude");
        m.sdAlt = r.real(7, "sd altitude");
    }
    return finishDecode(r, ctx, m);
}

void Gst::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("rms", rms)
            .field("sd_major", sdMajor)
            .field("sd_minor", sdMinor)
            .field("orientation", orientation)
            .field("sd_lat", sdLat)
            .field("sd_lon", sdLon)
            .field("sd_alt", sdAlt)
            .endObject();
}

} // namespace gnss::nmea
