// RMC: recommended minimum specific GNSS data (NMEA 0183 4.11 §6.3).
//
//   $--RMC,hhmmss.ss,A,llll.ll,a,yyyyy.yy,a,x.x,x.x,ddmmyy,x.x,a,a,a*hh
//          0 time  1 status 2 lat 3 4 lon 5 6 SOG (knots) 7 COG (deg true) 8 date
//          9 magnetic variation, 10 E/W, 11 mode (2.3+), 12 navigational status (4.10+)
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Rmc::kType{"RMC"};

bool decodeRmc(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Rmc>(s, ctx, 9, [&](FieldReader &r, Rmc &m) {
        m.time = r.time(0, "time");
        m.status = r.letter(1, "status");
        m.lat = r.latitude(2, "latitude");
        m.lon = r.longitude(4, "longitude");
        m.sogKnots = r.real(6, "speed");
        m.cog = r.real(7, "course");
        // Fields after the course are anchored at the end when a receiver prints extra empty
        // fields before the date (GeoS-5's no-fix RMC has two): date, variation, E/W, mode and,
        // in 4.10, the navigational status.
        const std::size_t n = r.count();
        const bool has410Status = n >= 13 && r.text(n - 1).size() == 1 && r.text(n - 2).size() == 1;
        const std::size_t standardCount = has410Status ? 13 : 12;
        const std::size_t shift = (n > standardCount && r.empty(8)) ? n - standardCount : 0;
        m.date = r.date(8 + shift, "date");
        m.magVar = r.real(9 + shift, "magnetic variation");
        if (m.magVar) {
            auto ew = r.letter(10 + shift, "variation direction");
            if (ew == 'W') *m.magVar = -*m.magVar;
        }
        m.mode = r.letter(11 + shift, "mode");
        m.navStatus = r.letter(12 + shift, "navigational status");
    });
}

void Rmc::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("status", status)
            .field("lat", lat)
            .field("lon", lon)
            .field("sog_knots", sogKnots)
            .field("cog", cog)
            .field("date", date)
            .field("mag_var", magVar)
            .field("mode", mode)
            .field("nav_status", navStatus)
            .endObject();
}

} // namespace gnss::nmea
