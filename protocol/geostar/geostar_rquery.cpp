// RQUERY: firmware version, telemetry and configuration (GeoS-5 NMEA v4.0, section 3.11).
//
//   $GPSGG,RQUERY,GEOS-5,V.x.xxx,ddmmyy,xxxxxxxx,xxxxxxxx,xxxxxxxx*hh
//          0      1 name 2 firmware 3 firmware date
//                                          4 status word (table 7)
//                                                   5 configuration register #1 (table 8)
//                                                            6 configuration register #2 (table 9)
// Example (docs/spec-notes.md, "RQUERY"; the spec prints the address as $GPGSGG):
//   $GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C
#include "core/decode_with.h"
#include "geostar/geostar_encode_util.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

#include <cstdio>

namespace gnss::geostar {

const MessageType Rquery::kType{"GPSGG,RQUERY"};

namespace {

std::optional<std::uint32_t> word(FieldReader &r, std::size_t i, const char *name) {
    if (r.text(i).size() > 8) {
        r.fail(i, name, QT_TRANSLATE_NOOP("Refusal", "longer than 8 hex digits"));
        return std::nullopt;
    }
    auto v = r.hex(i, name);
    if (!v) return std::nullopt;
    return static_cast<std::uint32_t>(*v);
}

// Longest receiver name and firmware printed: "GEOS-5" and "V.x.xxx" leave room, and with these
// the reply stays within NMEA's 82 characters.
constexpr std::size_t kMaxName = 10;
constexpr std::size_t kMaxFirmware = 16;

bool appendWord(std::string &body, const EncodedWord &w) {
    if (!w.ok()) return false;
    char hex[12];
    std::snprintf(hex, sizeof hex, ",%08X", static_cast<unsigned>(w.word));
    body += hex;
    return true;
}

} // namespace

bool decodeRquery(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Rquery>(s, ctx, 7, [](FieldReader &r, Rquery &m) {
        m.receiverName = r.text(1);
        m.firmware = r.text(2);
        m.firmwareVersion = m.firmware;
        if (m.firmwareVersion.substr(0, 2) == "V." || m.firmwareVersion.substr(0, 2) == "v.")
            m.firmwareVersion.remove_prefix(2);
        m.firmwareDate = r.date(3, "firmware date");
        const auto status = word(r, 4, "status word");
        const auto cfg1 = word(r, 5, "configuration register 1");
        const auto cfg2 = word(r, 6, "configuration register 2");
        if (!status || !cfg1 || !cfg2) {
            if (r.ok())
                r.failSentence(std::string(
                        QT_TRANSLATE_NOOP("Refusal", "RQUERY reply needs three hex words")));
        } else {
            m.status = StatusWord::decode(*status);
            m.config1 = ConfigRegister1::decode(*cfg1);
            m.config2 = ConfigRegister2::decode(*cfg2);
        }
    });
}

EncodeResult encodeRquery(const Rquery &m) {
    using namespace detail;
    std::string date;
    if (Refusal why = checkText("receiver name", m.receiverName, kMaxName); !why.empty())
        return refused(std::move(why));
    if (Refusal why = checkText("firmware", m.firmware, kMaxFirmware); !why.empty())
        return refused(std::move(why));
    if (Refusal why = formatDate(m.firmwareDate, "firmware date", date); !why.empty())
        return refused(std::move(why));
    std::string body = std::string(kAddress) + ",RQUERY,";
    body.append(m.receiverName).append(",").append(m.firmware).append(",").append(date);
    for (const EncodedWord &w : {m.status.encode(), m.config1.encode(), m.config2.encode()})
        if (!appendWord(body, w)) return refused(w.refusal);
    return sentence(body);
}

void Rquery::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("receiver_name", receiverName)
            .field("firmware", firmware)
            .field("firmware_version", firmwareVersion)
            .field("firmware_date", firmwareDate);
    w.key("status");
    status.writeJson(w);
    w.key("config1");
    config1.writeJson(w);
    w.key("config2");
    config2.writeJson(w);
    w.endObject();
}

} // namespace gnss::geostar
