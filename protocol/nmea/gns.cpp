// GNS: GNSS fix data (NMEA 0183 4.11 §6.3).
//
//   $--GNS,hhmmss.ss,llll.ll,a,yyyyy.yy,a,c--c,xx,x.x,x.x,x.x,x.x,x.x,a*hh
//          0 time    1 lat  2  3 lon   4  5 mode (one letter per system, any length)
//                                           6 sats used, 7 HDOP, 8 altitude MSL,
//                                           9 geoid separation, 10 DGPS age, 11 station,
//                                           12 navigational status (4.10+)
// Subsidiary per-system sentences (GP/GL/GA talkers after a GN one) have empty position fields.
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Gns::kType{"GNS"};

bool decodeGns(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Gns>(s, ctx, 6, [&](FieldReader &r, Gns &m) {
        m.time = r.time(0, "time");
        m.lat = r.latitude(1, "latitude");
        m.lon = r.longitude(3, "longitude");
        m.mode = r.text(5);
        m.satsUsed = r.integer(6, "satellites used");
        m.hdop = r.real(7, "HDOP");
        m.altMsl = r.real(8, "altitude");
        m.geoidSep = r.real(9, "geoid separation");
        // 4.10 adds the navigational status after the station id. Some receivers (GeoS-5 before
        // its 2022 revision) print it with one differential field fewer: the status is the last
        // field whenever that field is a single letter.
        const std::size_t n = r.count();
        const auto last = r.text(n - 1);
        const bool statusLast = n >= 12 && last.size() == 1 && last[0] >= 'A' && last[0] <= 'Z';
        const std::size_t end = statusLast ? n - 1 : n;
        if (10 < end) m.dgpsAge = r.real(10, "DGPS age");
        if (11 < end) m.dgpsStation = r.integer(11, "DGPS station");
        if (statusLast) m.navStatus = last[0];
    });
}

void Gns::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("lat", lat)
            .field("lon", lon)
            .field("mode", mode)
            .field("sats_used", satsUsed)
            .field("hdop", hdop)
            .field("alt_msl", altMsl)
            .field("geoid_sep", geoidSep)
            .field("dgps_age", dgpsAge)
            .field("dgps_station", dgpsStation)
            .field("nav_status", navStatus)
            .endObject();
}

} // namespace gnss::nmea
