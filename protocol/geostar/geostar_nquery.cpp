// NQUERY: NMEA output list and rates (GeoS-5 NMEA v4.0, section 3.12).
//
//   $GPSGG,NQUERY,p,r,v,c,c,c,c,c,c,c,c,c,c*hh
//          0      1 port (0/1), 2 rate code (0 10 Hz, 1 5 Hz, 2 2 Hz, 3 1 Hz),
//                 3 NMEA version (2 v2.x, 4 v4.10),
//                 4-13 per-message codes (0 off, 1 every s, 2 every 2 s, 3 every 20 s,
//                      R at the output rate) for GGA, GLL, GSA, GSV, RMC, VTG, ?, ZDA, DTM, RLM
// The field table of the spec was an image: the order is inferred (docs/spec-notes.md) from the one
// example ("port 1, 1 Hz, NMEA v2, outputs GGA, GSA, GSV, ZDA, DTM"); the 7th code's message is
// unknown and shown as such.
//   $GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71
#include "core/decode_with.h"
#include "geostar/geostar_encode_util.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

namespace gnss::geostar {

const MessageType Nquery::kType{"GPSGG,NQUERY"};

std::string_view nqueryCodeMeaning(char code) {
    switch (code) {
    case '0': return "off";
    case '1': return "every 1 s";
    case '2': return "every 2 s";
    case '3': return "every 20 s";
    case 'R': return "at the output rate";
    default: return "unknown";
    }
}

bool decodeNquery(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Nquery>(s, ctx, 4, [](FieldReader &r, Nquery &m) {
        m.port = r.integer(1, "port");
        m.rateCode = r.integer(2, "rate code");
        m.nmeaVersion = r.integer(3, "NMEA version");
        if (m.rateCode && rateCodeToHz(*m.rateCode) == 0)
            r.fail(2, "rate code", QT_TRANSLATE_NOOP("Refusal", "not 0-3"));
        for (std::size_t i = 0; i < Nquery::kMessages && 4 + i < r.count(); ++i) {
            const auto c = r.letter(4 + i, "message rate code");
            if (!c) continue;
            if (nqueryCodeMeaning(*c) == "unknown")
                r.fail(4 + i, "message rate code", QT_TRANSLATE_NOOP("Refusal", "not 0-3/R"));
            m.codes[i] = *c;
            m.codeCount = i + 1;
        }
        if (r.count() > 4 + Nquery::kMessages)
            r.failSentence(std::string(
                    QT_TRANSLATE_NOOP("Refusal", "NQUERY reply has more than 10 message codes")));
    });
}

EncodeResult encodeNquery(const Nquery &m) {
    using namespace detail;
    std::string body = std::string(kAddress) + ",NQUERY";
    auto number = [&body](const std::optional<int> &v) {
        body += ',';
        if (v) body += std::to_string(*v);
    };
    if (m.port && *m.port != 0 && *m.port != 1)
        return refused(notOneOf("port", std::to_string(*m.port), "0, 1"));
    if (m.rateCode && rateCodeToHz(*m.rateCode) == 0)
        return refused(outOfRange("rate code", std::to_string(*m.rateCode), "0..3"));
    if (m.nmeaVersion && *m.nmeaVersion != 2 && *m.nmeaVersion != 4)
        return refused(notOneOf("NMEA version", std::to_string(*m.nmeaVersion), "2, 4"));
    if (m.codeCount > Nquery::kMessages)
        return refused(outOfRange("message rate codes", std::to_string(m.codeCount),
                                  "0.." + std::to_string(Nquery::kMessages)));
    number(m.port);
    number(m.rateCode);
    number(m.nmeaVersion);
    for (std::size_t i = 0; i < m.codeCount; ++i) {
        const char c = m.codes[i];
        if (c && nqueryCodeMeaning(c) == "unknown")
            return refused(notOneOf("message rate code", std::string(1, c), "0, 1, 2, 3, R"));
        body += ',';
        if (c) body += c;
    }
    return sentence(body);
}

void Nquery::writeJson(JsonWriter &w) const {
    w.beginObject().field("port", port).field("rate_code", rateCode);
    if (rateCode && rateCodeToHz(*rateCode))
        w.field("rate_hz", rateCodeToHz(*rateCode));
    else
        w.key("rate_hz").null();
    w.field("nmea_version", nmeaVersion).key("messages").beginArray();
    for (std::size_t i = 0; i < codeCount; ++i) {
        w.beginObject();
        if (kNames[i].empty())
            w.key("name").null().field("note", "unknown message (probably GNS or reserved)");
        else
            w.field("name", kNames[i]);
        w.field("field", static_cast<int>(i + 4));
        if (codes[i])
            w.field("code", codes[i]).field("output", nqueryCodeMeaning(codes[i]));
        else
            w.key("code").null().key("output").null();
        w.endObject();
    }
    w.endArray().endObject();
}

} // namespace gnss::geostar
