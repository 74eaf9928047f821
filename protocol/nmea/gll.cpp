// GLL: geographic position, latitude/longitude (NMEA 0183 4.11 §6.3).
//
//   $--GLL,llll.ll,a,yyyyy.yy,a,hhmmss.ss,A,a*hh
//          0 lat  1  2 lon   3  4 time   5 status 6 mode (2.3+)
#include "nmea_messages.h"

namespace gnss::nmea {

const MessageType Gll::kType{"GLL"};

bool decodeGll(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Gll m;
    if (r.require(4)) {
        m.lat = r.latitude(0, "latitude");
        m.lon = r.longitude(2, "longitude");
        m.time = r.time(4, "time");
        m.status = r.letter(5, "status");
        m.mode = r.letter(6, "mode");
    }
    return finishDecode(r, ctx, m);
}

void Gll::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("lat", lat)
            .field("lon", lon)
            .field("time", time)
            .field("status", status)
            .field("mode", mode)
            .endObject();
}

} // namespace gnss::nmea
