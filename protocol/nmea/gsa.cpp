// GSA: GNSS DOP and active satellites (NMEA 0183 4.11 §6.3).
//
//   $--GSA,a,x,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,x.x,x.x,x.x,h*hh
//          0 mode (M/A), 1 fix (1 none, 2 2D, 3 3D), 2-13 satellite ids (12 slots),
//          PDOP, HDOP, VDOP, then the GNSS system id (4.10+).
// Receivers differ in the number of id slots, so the DOPs are found from the end: the system
// id, when present, is a bare integer after three DOP fields.
#include "nmea/nmea_messages.h"

#include "core/fixed_digits.h"

namespace gnss::nmea {

const MessageType Gsa::kType{"GSA"};

namespace {

constexpr DigitLayout kFourIds{"dd,dd,dd,dd"};

bool looksLikeSystemId(std::string_view last, std::string_view beforeLast, std::size_t count) {
    if (last.empty() || last.size() > 2) return false;
    for (char c : last)
        if (c < '0' || c > '9') return false;
    // With 12 id slots the 4.10 form has exactly 18 fields; otherwise the field before the
    // system id is VDOP, which carries a decimal point.
    return count == 18 || beforeLast.find('.') != std::string_view::npos;
}

} // namespace

bool decodeGsa(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Gsa>(s, ctx, 5, [&](FieldReader &r, Gsa &m) {
        m.mode = r.letter(0, "mode");
        r.integerInto(1, "fix", m.fix);
        std::size_t n = r.count();
        if (n >= 6 && looksLikeSystemId(r.text(n - 1), r.text(n - 2), n)) {
            r.integerInto(n - 1, "system id", m.systemId);
            --n;
        }
        m.pdop = r.real(n - 3, "PDOP");
        m.hdop = r.real(n - 2, "HDOP");
        m.vdop = r.real(n - 1, "VDOP");
        m.system = m.systemId ? constellationOfSystemId(*m.systemId)
                              : constellationOfTalker(s.talker());
        std::size_t i = 2;
        // Four two-digit ids at once while they are printed so ("01,02,03,04": fixed_digits.h).
        int four[4];
        while (i + 4 + 3 <= n && m.idCount + 4 <= Gsa::kMaxIds &&
               readFixedDigits<kFourIds>(s.fieldRun(i, 4), four)) {
            for (int id : four) {
                m.ids[m.idCount] = id;
                m.satellites[m.idCount] = ctx.mapSatellite(m.system, id);
                ++m.idCount;
            }
            i += 4;
        }
        for (; i + 3 < n; ++i) {
            int id; // none: an empty slot (or a malformed id, recorded)
            if (!r.integerValue(i, "satellite id", id) || m.idCount == Gsa::kMaxIds) continue;
            m.ids[m.idCount] = id;
            m.satellites[m.idCount] = ctx.mapSatellite(m.system, id);
            ++m.idCount;
        }
    });
}

void Gsa::writeJson(JsonWriter &w) const {
    w.beginObject().field("mode", mode).field("fix", fix).key("ids").beginArray();
    for (std::size_t i = 0; i < idCount; ++i) w.value(ids[i]);
    w.endArray().field("pdop", pdop).field("hdop", hdop).field("vdop", vdop);
    w.field("system_id", systemId).key("satellites").beginArray();
    for (std::size_t i = 0; i < idCount; ++i)
        w.beginObject()
                .field("system", toString(satellites[i].system))
                .field("prn", satellites[i].prn)
                .endObject();
    w.endArray().endObject();
}

} // namespace gnss::nmea
