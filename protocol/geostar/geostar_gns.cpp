// GNS as the GeoS-5 sends it (section 3.3). In a mixed-constellation mode a main $GNGNS sentence
// is followed by one subsidiary sentence per system (GP, GL, GA, GQ) whose position, mode, HDOP,
// altitude and geoid fields are empty; the receiver prints the per-system satellite count in the
// mode-indicator position (all checksums valid), so the standard decoder would read "11" as the
// mode and no satellite count:
//
//   $GPGNS,080606.00,,,,,11,,,,,001.0,0000,*68
//          0 time    1-4 empty, 5 satellites used (per system), 6-9 empty,
//                    10 DGPS age, 11 DGPS station (per system), 12 (navigational status: empty)
//
// The spec prints the RTK subsidiaries one comma short ($GPGNS,153632.00,,,,,09,,,,000.8,0100;
// restoring the comma gives the printed checksum): with 11 fields, age and station are 9 and 10.
// Anything else (main sentences, single-system sentences) goes to the standard decoder.
#include "geostar/geostar_gns.h"

#include "geostar/geostar_encode_util.h"
#include "geostar/geostar_encoders.h"
#include "nmea/nmea_messages.h"

#include <cstdio>

namespace gnss::geostar {
namespace {

bool digitsOnly(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    return true;
}

constexpr std::string_view kSubsidiaryTalkers[] = {"GP", "GL", "GA", "GQ"};

} // namespace

bool decodeGns(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    const std::size_t n = r.count();
    const bool subsidiary =
            n >= 7 && digitsOnly(r.text(5)) && r.empty(6) && r.empty(1) && r.empty(3);
    if (!subsidiary) return nmea::decodeGns(s, ctx);
    nmea::Gns m;
    m.time = r.time(0, "time");
    m.satsUsed = r.integer(5, "satellites used");
    const std::size_t age = n == 11 ? 9 : 10;
    m.dgpsAge = r.real(age, "DGPS age");
    m.dgpsStation = r.integer(age + 1, "DGPS station");
    m.navStatus = r.letter(12, "navigational status");
    return finishDecode(r, ctx, m);
}

EncodeResult encodeSubsidiaryGns(std::string_view talker, const nmea::Gns &m) {
    using namespace detail;
    bool known = false;
    for (std::string_view t : kSubsidiaryTalkers) known = known || t == talker;
    if (!known) return refused(notOneOf("talker", std::string(talker), "GP, GL, GA, GQ"));
    std::string time;
    if (Refusal why = formatTime(m.time, time); !why.empty()) return refused(std::move(why));
    if (!m.satsUsed)
        return refused(
                fieldRefusal(6, "satellites used", QT_TRANSLATE_NOOP("Refusal", "missing"), ""));
    if (*m.satsUsed < 0 || *m.satsUsed > 99)
        return refused(outOfRange("satellites used", std::to_string(*m.satsUsed), "0..99"));
    // The age is printed 000.0 (under 999.95 s, as the spec's range 0-999.9 rounds).
    if (m.dgpsAge && !(*m.dgpsAge >= 0 && *m.dgpsAge < 999.95))
        return refused(outOfRange("DGPS age", std::to_string(*m.dgpsAge), "0..999.9"));
    if (m.dgpsStation && (*m.dgpsStation < 0 || *m.dgpsStation > 4095))
        return refused(outOfRange("DGPS station", std::to_string(*m.dgpsStation), "0..4095"));
    if (m.navStatus && !(*m.navStatus >= 'A' && *m.navStatus <= 'Z'))
        return refused(notOneOf("navigational status", std::string(1, *m.navStatus), "A-Z"));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2sGNS,%s,,,,,%02d,,,,,", talker.data(), time.c_str(),
                  *m.satsUsed);
    std::string body = buf;
    if (m.dgpsAge || m.dgpsStation || m.navStatus) {
        if (m.dgpsAge) {
            std::snprintf(buf, sizeof buf, "%05.1f", *m.dgpsAge);
            body += buf;
        }
        body += ',';
        if (m.dgpsStation) {
            std::snprintf(buf, sizeof buf, "%04d", *m.dgpsStation);
            body += buf;
        }
        body += ',';
        if (m.navStatus) body += *m.navStatus;
    }
    return sentence(body);
}

} // namespace gnss::geostar
