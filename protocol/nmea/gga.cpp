// GGA: Global Positioning System fix data (NMEA 0183 4.11 §6.3).
//
//   $--GGA,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx*hh
//          0 time    1 lat  2  3 lon  4  5 quality
//                                         6 sats used, 7 HDOP, 8 altitude MSL, 9 M,
//                                         10 geoid separation, 11 M, 12 DGPS age, 13 station
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Gga::kType{"GGA"};

void readGgaFields(FieldReader &r, GgaFields &m) {
    m.time = r.time(0, "time");
    m.lat = r.latitude(1, "latitude");
    m.lon = r.longitude(3, "longitude");
    m.quality = r.integer(5, "quality");
    m.satsUsed = r.integer(6, "satellites used");
    m.hdop = r.real(7, "HDOP");
    m.altMsl = r.real(8, "altitude");
    m.geoidSep = r.real(10, "geoid separation");
    m.dgpsAge = r.real(12, "DGPS age");
    m.dgpsStation = r.integer(13, "DGPS station");
}

bool decodeGga(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Gga>(s, ctx, 6, readGgaFields);
}

void writeGgaFieldsJson(JsonWriter &w, const GgaFields &f) {
    w.beginObject()
            .field("time", f.time)
            .field("lat", f.lat)
            .field("lon", f.lon)
            .field("quality", f.quality)
            .field("sats_used", f.satsUsed)
            .field("hdop", f.hdop)
            .field("alt_msl", f.altMsl)
            .field("geoid_sep", f.geoidSep)
            .field("dgps_age", f.dgpsAge)
            .field("dgps_station", f.dgpsStation)
            .endObject();
}

} // namespace gnss::nmea
