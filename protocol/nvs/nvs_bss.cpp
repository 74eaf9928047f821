// 4.6 PNVGBSS: base station statistics.
//
//   $PNVGBSS,x,x,x,x.xxx,x.x*hh
//            0 RTCM messages received, 1 received with errors, 2 received without errors,
//            3 distance to base station (m), 4 RTCM data age (s, 0-999.9; blank before the
//            first RTCM message)
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Bss::kType{"PNVGBSS"};

// The receiver's layout: distance in millimetres, age in tenths of a second.
const FieldRow<Bss> Bss::kFields[] = {
        {&Bss::rtcmTotal, "RTCM messages received", "rtcm_total", {0, 0, kMaxCount}},
        {&Bss::rtcmErrors, "RTCM messages with errors", "rtcm_errors", {0, 0, kMaxCount}},
        {&Bss::rtcmOk, "RTCM messages without errors", "rtcm_ok", {0, 0, kMaxCount}},
        {&Bss::baseDistance, "distance to base", "base_distance", {3, 0, kMaxMetres}},
        {&Bss::rtcmAge, "RTCM age", "rtcm_age", {1, 0, kMaxRtcmAge}},
};

EncodeResult encodeBss(const Bss &m) {
    return encodeRows(m, Bss::kFields);
}

} // namespace gnss::nvs
