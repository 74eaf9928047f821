// HDT: heading, true (NMEA 0183 4.11 §6.3).
//
//   $--HDT,x.x,T*hh
//          0 heading (degrees true), 1 T
#include "nmea_messages.h"

namespace gnss::nmea {

const MessageType Hdt::kType{"HDT"};

bool decodeHdt(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Hdt m;
    if (r.require(1)) m.heading = r.real(0, "heading");
    return finishDecode(r, ctx, m);
}

void Hdt::writeJson(JsonWriter &w) const {
    w.beginObject().field("heading", heading).endObject();
}

} // namespace gnss::nmea
