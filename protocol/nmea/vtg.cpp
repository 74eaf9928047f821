// VTG: course over ground and ground speed (NMEA 0183 4.11 §6.3).
//
//   $--VTG,x.x,T,x.x,M,x.x,N,x.x,K,a*hh
//          0 COG true, 1 T, 2 COG magnetic, 3 M, 4 SOG knots, 5 N, 6 SOG km/h, 7 K, 8 mode
// NMEA 1.x form without the unit letters: $--VTG,x.x,x.x,x.x,x.x (true, magnetic, knots, km/h).
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Vtg::kType{"VTG"};

bool decodeVtg(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Vtg>(s, ctx, 4, [&](FieldReader &r, Vtg &m) {
        if (r.text(1) == "T") {
            // Each value is followed by its unit letter; find values by their units, since
            // receivers drop the empty ones (GeoS-5 prints no 'M' after an empty magnetic course).
            const std::size_t n = r.count();
            for (std::size_t i = 1; i < n; ++i) {
                const auto u = r.text(i);
                if (u == "T")
                    m.cogTrue = r.real(i - 1, "course true");
                else if (u == "M")
                    m.cogMagnetic = r.real(i - 1, "course magnetic");
                else if (u == "N")
                    m.sogKnots = r.real(i - 1, "speed knots");
                else if (u == "K") {
                    m.sogKmh = r.real(i - 1, "speed km/h");
                    m.mode = r.letter(i + 1, "mode");
                    break;
                }
            }
        } else {
            m.cogTrue = r.real(0, "course true");
            m.cogMagnetic = r.real(1, "course magnetic");
            m.sogKnots = r.real(2, "speed knots");
            m.sogKmh = r.real(3, "speed km/h");
        }
    });
}

void Vtg::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("cog_true", cogTrue)
            .field("cog_magnetic", cogMagnetic)
            .field("sog_knots", sogKnots)
            .field("sog_kmh", sogKmh)
            .field("mode", mode)
            .endObject();
}

} // namespace gnss::nmea
