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
#include "geostar_gns.h"

#include "nmea/nmea_messages.h"

namespace gnss::geostar {
namespace {

bool digitsOnly(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    return true;
}

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

} // namespace gnss::geostar
