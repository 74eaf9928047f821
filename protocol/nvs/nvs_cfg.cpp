// 4.8 PNVGCFG: save / erase RTK engine and port settings (command; the receiver confirms with a
// PNVGCFG reply, whose exact fields were an image in the spec: the first field is decoded and any
// further ones are kept as received).
//
//   $PNVGCFG,a*hh
//            0 W save to flash, E erase (restore defaults), R erase and restart
#include "nvs/nvs_encode_util.h"

namespace gnss::nvs {

const MessageType Cfg::kType{"PNVGCFG"};

bool decodeCfg(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Cfg>(s, ctx, 1, [&](FieldReader &r, Cfg &m) {
        m.action = r.text(0);
        if (m.action.empty()) r.fail(0, "action", QT_TRANSLATE_NOOP("Refusal", "empty"));
        for (std::size_t i = 1; i < s.fieldCount(); ++i) m.extra.push_back(r.text(i));
    });
}

void Cfg::writeJson(JsonWriter &w) const {
    std::string_view meaning = action == "W"   ? "save settings to flash"
                               : action == "E" ? "erase settings (restore defaults)"
                               : action == "R" ? "erase settings and restart"
                                               : "";
    w.beginObject().field("action", action).field("meaning", meaning);
    w.key("extra").beginArray();
    for (auto e : extra) w.value(e);
    w.endArray().endObject();
}

EncodeResult encodeCfg(char action) {
    if (auto err = checkLetter("PNVGCFG action", action, "WER"); !err.empty()) return refuse(err);
    return built(std::string("PNVGCFG,") + action);
}

} // namespace gnss::nvs
