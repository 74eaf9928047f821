// 4.16 PNVGTME, 4.17 PNVGTMU, 4.18 PNVGTMC: the time mark event (leading edge of the mark input).
//
//   $PNVGTME,x,x.x*hh          0 event counter, 1 time of week (s)
//   $PNVGTMU,x,hhmmss.s-s*hh   0 event counter, 1 UTC time
//   $PNVGTMC,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx*hh
//            as GGA: 0 time, 1-2 latitude, 3-4 longitude, 5 quality (NVS: 4 RTK, 5 float,
//            6 estimated), 6 satellites, 7 HDOP, 8 altitude MSL, 10 geoid separation,
//            12 differential age, 13 station id
#include "nvs/nvs_encode_util.h"
#include "nvs/nvs_output_fields.h"

#include "nmea/nmea_encoders.h"

namespace gnss::nvs {

const MessageType Tme::kType{"PNVGTME"};
const MessageType Tmu::kType{"PNVGTMU"};
const MessageType Tmc::kType{"PNVGTMC"};

// Time of week to the nanosecond ($PNVGTME,128,40327.564756284); the UTC time with the decimals
// it carries ($PNVGTMU,128,081248.547824228).
const FieldRow<Tme> Tme::kFields[] = {
        {&Tme::counter, "event counter", "counter", {0, 0, kMaxCount}},
        {&Tme::tow, "time of week", "tow", {9, 0, 604799.999999999}},
};
const FieldRow<Tmu> Tmu::kFields[] = {
        {&Tmu::counter, "event counter", "counter", {0, 0, kMaxCount}},
        {&Tmu::time, "time", "time"},
};

bool decodeTmc(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Tmc>(s, ctx, 6, nmea::readGgaFields);
}

EncodeResult encodeTme(const Tme &m) {
    return encodeRows(m, Tme::kFields);
}

EncodeResult encodeTmu(const Tmu &m) {
    return encodeRows(m, Tmu::kFields);
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
