// PNMRX101 (ECEF) and PNMRX104 (LLA) navigation initialisation.
//
//   $PNMRX101,x,y,z,c,t,w,n*hh
//             0-2 ECEF x, y, z (m; all three or none), 3 clock offset (Hz x 100 w.r.t. L1),
//             4 time of week (s), 5 week number, 6 channel count (12..16)
//   $PNMRX101,-742507,-5462738, 3196706,*4F   position, then a software reset
//   $PNMRX101,,,,,,,,,8,*51                   factory reset      } fix procedure code: not in
//   $PNMRX101, 4,*7D                          cold start mode    } the table, examples only
//
//   $PNMRX104,llll.llll,a,yyyyy.yyyy,b,h,c,t,w,n*hh
//             0-1 latitude, 2-3 longitude, 4 altitude MSL (m) — all or none —, 5 clock offset,
//             6 time of week, 7 week number, 8 channel count
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"

#include <cmath>

namespace gnss::nemerix {

const MessageType NavInit::kType{"PNMRX101"};
const MessageType LlaInit::kType{"PNMRX104"};

namespace {

const char *fixProcedureName(const std::optional<int> &code) {
    if (!code) return nullptr;
    switch (*code) {
    case 4: return "cold start";
    case 8: return "factory reset";
    default: return nullptr;
    }
}

// The tail's fields from field `first` (the clock offset), and their ranges.
void readTail(FieldReader &r, std::size_t first, NavInitTail &t) {
    t.clockOffset = r.integer(first, "clock offset");
    t.timeOfWeek = r.integer(first + 1, "time of week");
    t.week = r.integer(first + 2, "week number");
    t.channels = r.integer(first + 3, "channel count");
}
void checkTail(FieldReader &r, std::size_t first, const NavInitTail &t) {
    if (t.timeOfWeek && (*t.timeOfWeek < 0 || *t.timeOfWeek > 604799))
        r.fail(first + 1, "time of week", QT_TRANSLATE_NOOP("Refusal", "out of range"));
    if (t.week && (*t.week < 0 || *t.week > 9999))
        r.fail(first + 2, "week number", QT_TRANSLATE_NOOP("Refusal", "out of range"));
    if (t.channels && (*t.channels < 12 || *t.channels > 16))
        r.fail(first + 3, "channel count", QT_TRANSLATE_NOOP("Refusal", "out of range 12..16"));
}

void writeTail(JsonWriter &w, const NavInitTail &t) {
    w.field("clock_offset", t.clockOffset)
            .field("time_of_week", t.timeOfWeek)
            .field("week", t.week)
            .field("channels", t.channels);
}

} // namespace

bool decodeNavInit(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    NavInit m;
    // "$PNMRX101, 4,": one value alone is the fix procedure code (spec example), not ECEF x.
    bool onlyFirst = !r.empty(0);
    for (std::size_t i = 1; i < r.count(); ++i)
        if (!r.empty(i)) onlyFirst = false;
    if (onlyFirst) {
        m.fixProcedure = r.integer(0, "fix procedure");
        return finishDecode(r, ctx, m);
    }
    m.x = r.integer64(0, "ECEF x");
    m.y = r.integer64(1, "ECEF y");
    m.z = r.integer64(2, "ECEF z");
    readTail(r, 3, m);
    m.fixProcedure = r.integer(8, "fix procedure");
    if (r.ok() && (m.x.has_value() != m.y.has_value() || m.x.has_value() != m.z.has_value()))
        r.failSentence(std::string(
                QT_TRANSLATE_NOOP("Refusal", "ECEF x, y and z must be given together")));
    checkTail(r, 3, m);
    return finishDecode(r, ctx, m);
}

void NavInit::writeJson(JsonWriter &w) const {
    w.beginObject().field("ecef_x", x).field("ecef_y", y).field("ecef_z", z);
    writeTail(w, *this);
    w.field("fix_procedure", fixProcedure).key("fix_procedure_name");
    if (const char *n = fixProcedureName(fixProcedure))
        w.value(n);
    else
        w.null();
    w.field("resets_receiver", x.has_value()).endObject();
}

bool decodeLlaInit(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    LlaInit m;
    m.lat = r.latitude(0, "latitude");
    m.lon = r.longitude(2, "longitude");
    m.altitude = r.integer(4, "altitude");
    readTail(r, 5, m);
    if (r.ok() &&
        (m.lat.has_value() != m.lon.has_value() || m.lat.has_value() != m.altitude.has_value()))
        r.failSentence(std::string(QT_TRANSLATE_NOOP(
                "Refusal", "latitude, longitude and altitude must be given together")));
    checkTail(r, 5, m);
    return finishDecode(r, ctx, m);
}

void LlaInit::writeJson(JsonWriter &w) const {
    w.beginObject().field("lat", lat).field("lon", lon).field("altitude", altitude);
    writeTail(w, *this);
    w.field("resets_receiver", lat.has_value()).endObject();
}

namespace {

// Appends the optional fields, then trims empty trailing ones.
std::string joinFields(std::initializer_list<std::string> fields) {
    std::string out;
    std::size_t lastUsed = 0, i = 0;
    for (const auto &f : fields) {
        ++i;
        if (!f.empty()) lastUsed = i;
    }
    i = 0;
    for (const auto &f : fields) {
        if (++i > lastUsed) break;
        out += ",";
        out += f;
    }
    return out;
}

template <class T> std::string opt(const std::optional<T> &v) {
    return v ? std::to_string(*v) : std::string();
}

std::string checkCommonParams(const std::optional<int> &clock, const std::optional<int> &tow,
                              const std::optional<int> &week, const std::optional<int> &channels) {
    if (clock && (*clock < -999999 || *clock > 999999))
        return "clock offset: " + std::to_string(*clock) +
               " is out of range; accepted: -999999..999999 (Hz x 100)";
    if (tow && (*tow < 0 || *tow > 604799))
        return "time of week: " + std::to_string(*tow) + " is out of range; accepted: 0..604799 s";
    if (week && (*week < 0 || *week > 9999))
        return "week number: " + std::to_string(*week) + " is out of range; accepted: 0..9999";
    if (channels && (*channels < 12 || *channels > 16))
        return "channel count: " + std::to_string(*channels) + " is out of range; accepted: 12..16";
    return {};
}

// ddmm.mmmm / dddmm.mmmm from unsigned degrees.
std::string degreesMinutes(double deg, int degDigits) {
    const long long tenThousandths = std::llround(deg * 60.0 * 10000.0);
    const long long d = tenThousandths / (60 * 10000);
    const double minutes = static_cast<double>(tenThousandths % (60 * 10000)) / 10000.0;
    std::string ds = std::to_string(d);
    while (static_cast<int>(ds.size()) < degDigits) ds.insert(0, "0");
    std::string ms = formatFixed(minutes, 4);
    if (minutes < 10) ms.insert(0, "0");
    return ds + ms;
}

} // namespace

EncodeResult encodeNavInit(const NavInitParams &p, std::string_view prefix) {
    EncodeResult r;
    const bool anyPos = p.x || p.y || p.z, allPos = p.x && p.y && p.z;
    if (anyPos && !allPos) {
        r.error = "ECEF position: x, y and z must be given together";
        return r;
    }
    for (const auto *v : {&p.x, &p.y, &p.z}) {
        if (*v && (**v < -9999999 || **v > 9999999)) {
            r.error = "ECEF position: " + std::to_string(**v) +
                      " is out of range; accepted: -9999999..9999999 m";
            return r;
        }
    }
    r.error = checkCommonParams(p.clockOffset, p.timeOfWeek, p.week, p.channels);
    if (!r.ok()) return r;
    std::string fields = joinFields({opt(p.x), opt(p.y), opt(p.z), opt(p.clockOffset),
                                     opt(p.timeOfWeek), opt(p.week), opt(p.channels)});
    if (fields.empty()) {
        r.error = "PNMRX101: no parameter given";
        return r;
    }
    return buildCommand("101", fields + ",", prefix);
}

EncodeResult encodeLlaInit(const LlaInitParams &p, std::string_view prefix) {
    EncodeResult r;
    const bool anyPos = p.lat || p.lon || p.altitude, allPos = p.lat && p.lon && p.altitude;
    if (anyPos && !allPos) {
        r.error = "LLA position: latitude, longitude and altitude must be given together";
        return r;
    }
    if (p.lat && !(std::fabs(*p.lat) <= 90.0)) {
        r.error = "latitude: " + formatFixed(*p.lat, 6) + " is out of range; accepted: -90..90 deg";
        return r;
    }
    if (p.lon && !(std::fabs(*p.lon) <= 180.0)) {
        r.error = "longitude: " + formatFixed(*p.lon, 6) +
                  " is out of range; accepted: -180..180 deg";
        return r;
    }
    if (p.altitude && (*p.altitude < -99999 || *p.altitude > 999999)) {
        r.error = "altitude: " + std::to_string(*p.altitude) +
                  " is out of range; accepted: -99999..999999 m";
        return r;
    }
    r.error = checkCommonParams(p.clockOffset, p.timeOfWeek, p.week, p.channels);
    if (!r.ok()) return r;
    std::string lat, ns, lon, ew;
    if (p.lat) {
        lat = degreesMinutes(std::fabs(*p.lat), 2);
        ns = *p.lat < 0 ? "S" : "N";
        lon = degreesMinutes(std::fabs(*p.lon), 3);
        ew = *p.lon < 0 ? "W" : "E";
    }
    std::string fields = joinFields({lat, ns, lon, ew, opt(p.altitude), opt(p.clockOffset),
                                     opt(p.timeOfWeek), opt(p.week), opt(p.channels)});
    if (fields.empty()) {
        r.error = "PNMRX104: no parameter given";
        return r;
    }
    return buildCommand("104", fields, prefix);
}

} // namespace gnss::nemerix
