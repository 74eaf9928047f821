// GSV: GNSS satellites in view (NMEA 0183 4.11 §6.3).
//
//   $--GSV,x,x,xx,xx,xx,xxx,xx,....,xx,xx,xxx,xx,h*hh
//          0 total sentences, 1 sentence number, 2 satellites in view,
//          then per satellite: id, elevation (deg, may be negative), azimuth (deg), SNR (dB-Hz),
//          up to four per sentence, then the signal id (4.10+).
// The constellation comes from the talker (GP, GL, GA, GB/BD, GQ, GI); GN and GP fall back to
// the 2.x numbering ranges (see core/satellite.h).
#include "nmea/nmea_messages.h"

#include "core/fixed_digits.h"
#include "core/satellite_json.h"

namespace gnss::nmea {

const MessageType Gsv::kType{"GSV"};

namespace {
constexpr DigitLayout kPlainSatellite{"dd,dd,ddd,dd"}; // id, elevation, azimuth, SNR
} // namespace

bool decodeGsv(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Gsv>(s, ctx, 3, [&](FieldReader &r, Gsv &m) {
        r.integerInto(0, "total sentences", m.total);
        r.integerInto(1, "sentence number", m.index);
        r.integerInto(2, "satellites in view", m.inView);
        m.system = constellationOfTalker(s.talker());
        std::size_t n = r.count();
        if (n > 3 && (n - 3) % 4 == 1) {
            r.integerInto(n - 1, "signal id", m.signalId);
            --n;
        }
        for (std::size_t i = 3; i < n; i += 4) {
            // Nearly every satellite is printed "01,05,000,31": read at once (fixed_digits.h),
            // its values checked while in registers (two digits and three can only be too big).
            int plain[4];
            if (i + 4 <= n && m.satelliteCount < Gsv::kMaxSatellites &&
                readFixedDigits<kPlainSatellite>(s.fieldRun(i, 4), plain)) {
                m.satellites[m.satelliteCount++] =
                        GsvSatellite{plain[0], ctx.mapSatellite(m.system, plain[0]), plain[1],
                                     plain[2], plain[3]};
                if (plain[1] > 90)
                    r.fail(i + 1, "elevation", QT_TRANSLATE_NOOP("Refusal", "out of range"));
                if (plain[2] > 360)
                    r.fail(i + 2, "azimuth", QT_TRANSLATE_NOOP("Refusal", "out of range"));
                continue;
            }
            int id; // none: an empty padding slot (or a malformed id, recorded)
            if (!r.integerValue(i, "satellite id", id)) continue;
            if (m.satelliteCount == Gsv::kMaxSatellites) {
                r.failSentence(std::string(
                        QT_TRANSLATE_NOOP("Refusal", "too many satellites in one GSV sentence")));
                break;
            }
            GsvSatellite &sv = m.satellites[m.satelliteCount++];
            sv = GsvSatellite{}; // the slot whole first (a SlotArray's are not cleared)
            sv.id = id;
            sv.sat = ctx.mapSatellite(m.system, id);
            r.integerInto(i + 1, "elevation", sv.elevation);
            r.integerInto(i + 2, "azimuth", sv.azimuth);
            r.integerInto(i + 3, "SNR", sv.snr);
            if (sv.elevation && (*sv.elevation < -90 || *sv.elevation > 90))
                r.fail(i + 1, "elevation", QT_TRANSLATE_NOOP("Refusal", "out of range"));
            if (sv.azimuth && (*sv.azimuth < 0 || *sv.azimuth > 360))
                r.fail(i + 2, "azimuth", QT_TRANSLATE_NOOP("Refusal", "out of range"));
        }
        if (m.total && m.index && (*m.index < 1 || *m.index > *m.total))
            r.failSentence(refusal(QT_TRANSLATE_NOOP("Refusal", "sentence number outside 1..%1"),
                                   {std::to_string(*m.total)}));
    });
}

void Gsv::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("total", total)
            .field("index", index)
            .field("in_view", inView)
            .field("signal_id", signalId)
            .key("satellites")
            .beginArray();
    for (std::size_t i = 0; i < satelliteCount; ++i)
        beginSatelliteJson(w, satellites[i], "id", satellites[i].id).endObject();
    w.endArray().endObject();
}

} // namespace gnss::nmea
