// 4.1 PNVGVER: receiver and firmware information.
//
//   request  $PNVGVER*4E
//   reply    $PNVGVER,c-c,c-c,xxxx,c-c,xxxx*hh
//                     0 manufacturer (NVS), 1 device (RTK / RTA), 2 RTK FW version,
//                     3 CSM HW (CSM24), 4 CSM FW version
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

#include "core/sentence_builder.h"

namespace gnss::nvs {

const MessageType Ver::kType{"PNVGVER"};

// The texts as the receiver prints them (firmware versions keep their leading zeros).
const FieldRow<Ver> Ver::kFields[] = {
        {&Ver::manufacturer, "manufacturer", "manufacturer"},
        {&Ver::device, "device", "device"},
        {&Ver::rtkFw, "RTK firmware", "rtk_fw"},
        {&Ver::csmHw, "CSM hardware", "csm_hw"},
        {&Ver::csmFw, "CSM firmware", "csm_fw"},
};

// The request has no fields, the reply all five.
bool decodeVer(const Sentence &s, DecodeContext &ctx) {
    const bool request = s.fieldCount() == 0;
    return decodeWith<Ver>(s, ctx, request ? 0 : 5, [&](FieldReader &r, Ver &m) {
        m.request = request;
        if (!request) readFields(r, m, Ver::kFields);
    });
}

EncodeResult encodeVersionRequest() {
    return {{buildSentence("PNVGVER")}, {}};
}

// A request gives "$PNVGVER".
EncodeResult encodeVer(const Ver &m) {
    return m.request ? encodeVersionRequest() : encodeRows(m, Ver::kFields);
}

} // namespace gnss::nvs
