// DTM: datum reference (NMEA 0183 4.11 §6.3).
//
//   $--DTM,ccc,a,x.x,a,x.x,a,x.x,ccc*hh
//          0 local datum (W84, W72, S85, P90, 999 user), 1 subdivision,
//          2 latitude offset (minutes), 3 N/S, 4 longitude offset (minutes), 5 E/W,
//          6 altitude offset (m), 7 reference datum
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Dtm::kType{"DTM"};

bool decodeDtm(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Dtm>(s, ctx, 1, [&](FieldReader &r, Dtm &m) {
        m.datum = r.text(0);
        m.subdivision = r.text(1);
        m.latOffset = r.real(2, "latitude offset");
        if (m.latOffset && r.text(3) == "S") *m.latOffset = -*m.latOffset;
        m.lonOffset = r.real(4, "longitude offset");
        if (m.lonOffset && r.text(5) == "W") *m.lonOffset = -*m.lonOffset;
        m.altOffset = r.real(6, "altitude offset");
        m.referenceDatum = r.text(7);
    });
}

void Dtm::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("datum", datum)
            .field("subdivision", subdivision)
            .field("lat_offset_min", latOffset)
            .field("lon_offset_min", lonOffset)
            .field("alt_offset", altOffset)
            .field("reference_datum", referenceDatum)
            .endObject();
}

} // namespace gnss::nmea
