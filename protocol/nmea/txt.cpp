// TXT: text transmission (NMEA 0183 4.11 §6.3).
//
//   $--TXT,xx,xx,xx,c--c*hh
//          0 total sentences, 1 sentence number, 2 text identifier, 3 text
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Txt::kType{"TXT"};

bool decodeTxt(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Txt>(s, ctx, 4, [&](FieldReader &r, Txt &m) {
        m.total = r.integer(0, "total");
        m.number = r.integer(1, "number");
        m.id = r.integer(2, "identifier");
        // The text may itself contain commas on sloppy receivers: keep everything after field 2.
        const auto body = s.body();
        std::size_t pos = 0;
        for (int commas = 0; commas < 4 && pos != std::string_view::npos; ++commas)
            pos = body.find(',', pos == 0 ? 0 : pos + 1);
        m.text = pos == std::string_view::npos ? r.text(3) : body.substr(pos + 1);
    });
}

void Txt::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("total", total)
            .field("number", number)
            .field("id", id)
            .field("text", text)
            .endObject();
}

} // namespace gnss::nmea
