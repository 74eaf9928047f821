// RLM: Galileo return link message (GeoS-5 NMEA v4.0, section 3.10). Not in the core: NMEA 0183
// has no RLM; GeoStar sends it under the GP talker.
//
//   $GPRLM,hhhhhhhhhhhhhhh,hhmmss.ss,h,h--h*hh
//          0 beacon 15HEX ID (COSPAS-SARSAT), 1 time, 2 message code (one hex digit),
//          3 parameters: 4 hex digits (16 bits, short message) or 24 (96 bits, long message)
//   $GPRLM,123456789ABCD12,000128.00,3,333344445555666677778888*64
// Message codes: 0 reserved, 1 acknowledgement, 2 command, 3 message, 4-E reserved, F test.
#include "core/decode_with.h"
#include "geostar/geostar_encode_util.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

namespace gnss::geostar {

const MessageType Rlm::kType{"RLM"};

using detail::isHex;

bool decodeRlm(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Rlm>(s, ctx, 4, [](FieldReader &r, Rlm &m) {
        m.beaconId = r.text(0);
        if (m.beaconId.size() != 15 || !isHex(m.beaconId))
            r.fail(0, "beacon id", QT_TRANSLATE_NOOP("Refusal", "not 15 hex digits"));
        m.time = r.time(1, "time");
        const std::string_view code = r.text(2);
        if (code.size() != 1 || !isHex(code))
            r.fail(2, "message code", QT_TRANSLATE_NOOP("Refusal", "not one hex digit"));
        else
            m.messageCode = static_cast<int>(*r.hex(2, "message code"));
        m.parameters = r.text(3);
        if ((m.parameters.size() != 4 && m.parameters.size() != 24) || !isHex(m.parameters))
            r.fail(3, "parameters", QT_TRANSLATE_NOOP("Refusal", "not 4 or 24 hex digits"));
    });
}

EncodeResult encodeRlm(const Rlm &m) {
    using namespace detail;
    if (m.beaconId.size() != 15 || !isHex(m.beaconId))
        return refused(fieldRefusal(1, "beacon id",
                                    QT_TRANSLATE_NOOP("Refusal", "not 15 hex digits"), m.beaconId));
    std::string time;
    if (Refusal why = formatTime(m.time, time); !why.empty()) return refused(std::move(why));
    if (!m.messageCode || *m.messageCode < 0 || *m.messageCode > 15)
        return refused(fieldRefusal(3, "message code",
                                    QT_TRANSLATE_NOOP("Refusal", "not one hex digit"),
                                    m.messageCode ? std::to_string(*m.messageCode) : ""));
    if ((m.parameters.size() != 4 && m.parameters.size() != 24) || !isHex(m.parameters))
        return refused(fieldRefusal(4, "parameters",
                                    QT_TRANSLATE_NOOP("Refusal", "not 4 or 24 hex digits"),
                                    m.parameters));
    std::string body = "GPRLM,"; // GP only (3.10)
    body.append(m.beaconId).append(",").append(time).append(",");
    body += "0123456789ABCDEF"[*m.messageCode];
    body.append(",").append(m.parameters);
    return sentence(body);
}

std::string_view Rlm::serviceName() const {
    if (!messageCode) return {};
    switch (*messageCode) {
    case 1: return "acknowledgement";
    case 2: return "command";
    case 3: return "message";
    case 15: return "test";
    default: return "reserved";
    }
}

void Rlm::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("beacon_id", beaconId)
            .field("time", time)
            .field("message_code", messageCode)
            .field("service", serviceName())
            .field("parameters", parameters)
            .field("length", std::string_view(parameters.size() == 24 ? "long" : "short"))
            .endObject();
}

} // namespace gnss::geostar
