// HDT: heading, true (NMEA 0183 4.11 §6.3).
//
//   $--HDT,x.x,T*hh
//          0 heading (degrees true), 1 T
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Hdt::kType{"HDT"};

bool decodeHdt(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Hdt>(s, ctx, 1,
                           [](FieldReader &r, Hdt &m) { m.heading = r.real(0, "heading"); });
}

void Hdt::writeJson(JsonWriter &w) const {
    w.beginObject().field("heading", heading).endObject();
}

} // namespace gnss::nmea
