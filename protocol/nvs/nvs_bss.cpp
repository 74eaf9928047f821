// 4.6 PNVGBSS: base station statistics.
//
//   $PNVGBSS,x,x,x,x.xxx,x.x*hh
//            0 RTCM messages received, 1 received with errors, 2 received without errors,
//            3 distance to base station (m), 4 RTCM data age (s, 0-999.9; blank before the
//            first RTCM message)
#include "nvs_messages.h"

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

} // namespace gnss::nvs
