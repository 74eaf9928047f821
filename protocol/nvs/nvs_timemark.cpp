// 4.16 PNVGTME, 4.17 PNVGTMU, 4.18 PNVGTMC: the time mark event (leading edge of the mark input).
//
//   $PNVGTME,x,x.x*hh          0 event counter, 1 time of week (s)
//   $PNVGTMU,x,hhmmss.s-s*hh   0 event counter, 1 UTC time
//   $PNVGTMC,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx*hh
//            as GGA: 0 time, 1-2 latitude, 3-4 longitude, 5 quality (NVS: 4 RTK, 5 float,
//            6 estimated), 6 satellites, 7 HDOP, 8 altitude MSL, 10 geoid separation,
//            12 differential age, 13 station id
#include "nvs_messages.h"

namespace gnss::nvs {

const MessageType Tme::kType{"PNVGTME"};
const MessageType Tmu::kType{"PNVGTMU"};
const MessageType Tmc::kType{"PNVGTMC"};

bool decodeTme(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Tme m;
    if (r.require(2)) {
        m.counter = r.integer64(0, "event counter");
        m.tow = r.real(1, "time of week");
    }
    return finishDecode(r, ctx, m);
}

void Tme::writeJson(JsonWriter &w) const {
    w.beginObject().field("counter", counter).field("tow", tow).endObject();
}

bool decodeTmu(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Tmu m;
    if (r.require(2)) {
        m.counter = r.integer64(0, "event counter");
        m.time = r.time(1, "time");
    }
    return finishDecode(r, ctx, m);
}

void Tmu::writeJson(JsonWriter &w) const {
    w.beginObject().field("counter", counter).field("time", time).endObject();
}

bool decodeTmc(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Tmc m;
    if (r.require(6)) nmea::readGgaFields(r, m);
    return finishDecode(r, ctx, m);
}

} // namespace gnss::nvs
