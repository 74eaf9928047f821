// 4.1 PNVGVER: receiver and firmware information.
//
//   request  $PNVGVER*4E
//   reply    $PNVGVER,c-c,c-c,xxxx,c-c,xxxx*hh
//                     0 manufacturer (NVS), 1 device (RTK / RTA), 2 RTK FW version,
//                     3 CSM HW (CSM24), 4 CSM FW version
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

#include "core/sentence_builder.h"

namespace gnss::nvs {

const MessageType Ver::kType{"PNVGVER"};

bool decodeVer(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Ver m;
    m.request = s.fieldCount() == 0;
    if (!m.request && r.require(5)) {
        m.manufacturer = r.str(0);
        m.device = r.str(1);
        m.rtkFw = r.str(2);
        m.csmHw = r.str(3);
        m.csmFw = r.str(4);
    }
    return finishDecode(r, ctx, m);
}

void Ver::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("manufacturer", manufacturer)
            .field("device", device)
            .field("rtk_fw", rtkFw)
            .field("csm_hw", csmHw)
            .field("csm_fw", csmFw)
            .endObject();
}

EncodeResult encodeVersionRequest() {
    return {{buildSentence("PNVGVER")}, {}};
}

// The texts as the receiver prints them (firmware versions keep their leading zeros).
EncodeResult encodeVer(const Ver &m) {
    if (m.request) return encodeVersionRequest();
    OutputFields f(Ver::kType.name);
    f.text("manufacturer", m.manufacturer)
            .text("device", m.device)
            .text("RTK firmware", m.rtkFw)
            .text("CSM hardware", m.csmHw)
            .text("CSM firmware", m.csmFw);
    return f.build();
}

} // namespace gnss::nvs
