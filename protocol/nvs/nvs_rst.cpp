// 4.3 PNVGRST: force receiver reset (command only; no reply, the receiver restarts).
//
//   $PNVGRST,a*hh
//            0 reset type: F keep user settings + cold start, W keep user settings + warm restart
#include "nvs/nvs_encode_util.h"

namespace gnss::nvs {

const MessageType Rst::kType{"PNVGRST"};

bool decodeRst(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Rst>(s, ctx, 1, [&](FieldReader &r, Rst &m) {
        m.type = r.letter(0, "reset type");
        if (m.type && *m.type != 'F' && *m.type != 'W')
            r.fail(0, "reset type", QT_TRANSLATE_NOOP("Refusal", "not F or W"));
    });
}

void Rst::writeJson(JsonWriter &w) const {
    w.beginObject().field("type", type);
    w.field("meaning", !type ? "" : *type == 'F' ? "cold start" : "warm restart").endObject();
}

EncodeResult encodeRst(char type) {
    if (auto err = checkLetter("PNVGRST reset type", type, "FW"); !err.empty()) return refuse(err);
    return built(std::string("PNVGRST,") + type);
}

} // namespace gnss::nvs
