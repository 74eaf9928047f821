// 4.16 PNVGTME, 4.17 PNVGTMU, 4.18 PNVGTMC: the time mark event (leading edge of the mark input).
//
//   $PNVGTME,x,x.x*hh          0 event counter, 1 time of week (s)
//   $PNVGTMU,x,hhmmss.s-s*hh   0 event counter, 1 UTC time
//   $PNVGTMC,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx*hh
//            as GGA: 0 time, 1-2 latitude, 3-4 longitude, 5 quality (NVS: 4 RTK, 5 float,
//            6 estimated), 6 satellites, 7 HDOP, 8 altitude MSL, 10 geoid separation,
//            12 differential age, 13 station id
#include "nvs_encode_util.h"
#include "nvs_output_fields.h"

#include "nmea/nmea_encoders.h"

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

// Time of week to the nanosecond ($PNVGTME,128,40327.564756284).
EncodeResult encodeTme(const Tme &m) {
    OutputFields f(Tme::kType.name);
    f.integer("event counter", m.counter, 0, kMaxCount)
            .real("time of week", m.tow, 9, 0, 604799.999999999);
    return f.build();
}

// The time with the decimals it carries ($PNVGTMU,128,081248.547824228).
EncodeResult encodeTmu(const Tmu &m) {
    OutputFields f(Tmu::kType.name);
    f.integer("event counter", m.counter, 0, kMaxCount).time("time", m.time);
    return f.build();
}

// The GGA layout, written by the GGA encoder (one layout for both); the time with the decimals it
// carries, the position with those PNVGNME sets.
EncodeResult encodeTmc(const Tmc &m, int positionDecimals) {
    if (Refusal why = checkSetting("nmea.position_decimals", std::to_string(positionDecimals));
        !why.empty())
        return refuse(std::move(why));
    // Checked here, field by field, for what the GGA encoder takes as given.
    OutputFields check(Tmc::kType.name);
    check.time("time", m.time)
            .real("latitude", m.lat, 9, -90, 90)
            .real("longitude", m.lon, 9, -180, 180)
            .integer("quality", m.quality, 0, 6)
            .integer("satellites used", m.satsUsed, 0, 99)
            .real("HDOP", m.hdop, 1, 0, kMaxDop)
            .real("altitude", m.altMsl, 3, -kMaxMetres, kMaxMetres)
            .real("geoid separation", m.geoidSep, 3, -kMaxMetres, kMaxMetres)
            .real("DGPS age", m.dgpsAge, 1, 0, kMaxRtcmAge)
            .integer("DGPS station", m.dgpsStation, 0, 1023); // 4.18: 0000-1023
    if (m.quality && *m.quality == 3)                         // 4.18: 0, 1, 2, 4, 5, 6
        check.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not one of: %3"),
                             {"PNVGTMC quality", "3", "0, 1, 2, 4, 5, 6"}));
    if (!check.ok()) return check.build();
    nmea::Gga gga;
    static_cast<nmea::GgaFields &>(gga) = m;
    nmea::EncodeFormat format;
    format.timeDecimals = m.time ? m.time->decimals : format.timeDecimals;
    format.positionDecimals = positionDecimals;
    const std::string line = nmea::encodeGga("GP", gga, format); // "$GPGGA,...*hh"
    return built(std::string(Tmc::kType.name) + line.substr(6, line.size() - 6 - 3));
}

} // namespace gnss::nvs
