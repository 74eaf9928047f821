// Query: $ttllQ,c--c — talker tt asks listener ll for sentence c--c (NMEA 0183 4.11 §5.3.4).
// NVS uses it to request single sentences: $GPGPQ,PNVGTST*21.
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Query::kType{"query"};

bool decodeQuery(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Query>(s, ctx, 1, [&](FieldReader &r, Query &m) {
        m.requester = s.address().substr(0, 2);
        m.listener = s.address().substr(2, 2);
        m.address = r.text(0);
        if (m.address.empty()) r.fail(0, "address", QT_TRANSLATE_NOOP("Refusal", "empty"));
    });
}

void Query::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("requester", requester)
            .field("listener", listener)
            .field("address", address)
            .endObject();
}

} // namespace gnss::nmea
