// ZDA: time and date (NMEA 0183 4.11 §6.3).
//
//   $--ZDA,hhmmss.ss,xx,xx,xxxx,xx,xx*hh
//          0 time, 1 day, 2 month, 3 year, 4 local zone hours, 5 local zone minutes
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Zda::kType{"ZDA"};

namespace {
constexpr int kFirstYear = 1980;
constexpr int kLastYear = 9999;
} // namespace

bool decodeZda(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Zda>(s, ctx, 4, [&](FieldReader &r, Zda &m) {
        m.time = r.time(0, "time");
        auto d = r.integer(1, "day");
        auto mo = r.integer(2, "month");
        auto y = r.integer(3, "year");
        if (d && mo && y) {
            if (*d < 1 || *d > 31) r.fail(1, "day", QT_TRANSLATE_NOOP("Refusal", "out of range"));
            if (*mo < 1 || *mo > 12)
                r.fail(2, "month", QT_TRANSLATE_NOOP("Refusal", "out of range"));
            // Four digits, and no satellite gave a date before GPS began (1980). A year of two
            // digits or of nine is a broken receiver, and a date of such a year would put its
            // epochs ages away from the rest of a log (time arithmetic overflowed on it).
            if (*y < kFirstYear || *y > kLastYear)
                r.fail(3, "year", QT_TRANSLATE_NOOP("Refusal", "out of range"));
            m.date = Date{*y, *mo, *d};
        }
        m.tzHours = r.integer(4, "zone hours");
        m.tzMinutes = r.integer(5, "zone minutes");
    });
}

void Zda::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("date", date)
            .field("tz_hours", tzHours)
            .field("tz_minutes", tzMinutes)
            .endObject();
}

} // namespace gnss::nmea
