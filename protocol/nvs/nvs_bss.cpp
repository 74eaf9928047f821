// 4.6 PNVGBSS: base station statistics.
//
//   $PNVGBSS,x,x,x,x.xxx,x.x*hh
//            0 RTCM messages received, 1 received with errors, 2 received without errors,
//            3 distance to base station (m), 4 RTCM data age (s, 0-999.9; blank before the
//            first RTCM message)
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Bss::kType{"PNVGBSS"};

bool decodeBss(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Bss m;
    if (r.require(4)) {
        m.rtcmTotal = r.integer64(0, "RTCM messages received");
        m.rtcmErrors = r.integer64(1, "RTCM messages with errors");
        m.rtcmOk = r.integer64(2, "RTCM messages without errors");
        m.baseDistance = r.real(3, "distance to base");
        m.rtcmAge = r.real(4, "RTCM age");
    }
    return finishDecode(r, ctx, m);
}

void Bss::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("rtcm_total", rtcmTotal)
            .field("rtcm_errors", rtcmErrors)
            .field("rtcm_ok", rtcmOk)
            .field("base_distance", baseDistance)
            .field("rtcm_age", rtcmAge)
            .endObject();
}

// The receiver's layout: distance in millimetres, age in tenths of a second.
EncodeResult encodeBss(const Bss &m) {
    OutputFields f(Bss::kType.name);
    f.integer("RTCM messages received", m.rtcmTotal, 0, kMaxCount)
            .integer("RTCM messages with errors", m.rtcmErrors, 0, kMaxCount)
            .integer("RTCM messages without errors", m.rtcmOk, 0, kMaxCount)
            .real("distance to base", m.baseDistance, 3, 0, kMaxMetres)
            .real("RTCM age", m.rtcmAge, 1, 0, kMaxRtcmAge);
    return f.build();
}

} // namespace gnss::nvs
