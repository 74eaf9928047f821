// 4.5 PNVGRZB: extended query — sets or clears the list of output messages (command only).
//
//   $PNVGRZB*45                       clear the current port's list
//   $PNVGRZB,PORT,2*6E                clear UART2's list
//   $PNVGRZB[,PORT,x],c-c,x[,c-c,x]*hh  add messages with output rates (in PVT intervals)
//            PORT,x: 0 current, 1 UART1, 2 UART2, 3 USB (optional)
//            c-c: 3 last characters of a standard address, or a proprietary address (all 7
//            characters or the 3 last ones); x: output every x-th PVT
#include "nvs/nvs_encode_util.h"

namespace gnss::nvs {

const MessageType Rzb::kType{"PNVGRZB"};

bool decodeRzb(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Rzb m;
    std::size_t i = 0;
    if (s.fieldCount() >= 2 && r.text(0) == "PORT") {
        m.port = r.integer(1, "port");
        i = 2;
    }
    for (; i < s.fieldCount() && r.ok(); i += 2) {
        if (r.empty(i) && i + 1 >= s.fieldCount()) break; // trailing comma
        if (r.empty(i)) {
            r.fail(i, "message address", QT_TRANSLATE_NOOP("Refusal", "empty"));
            break;
        }
        if (i + 1 >= s.fieldCount()) {
            r.fail(i, "output rate", QT_TRANSLATE_NOOP("Refusal", "missing"));
            break;
        }
        const auto rate = r.integer(i + 1, "output rate");
        if (rate)
            m.entries.push_back({std::string(r.text(i)), *rate});
        else if (r.ok())
            r.fail(i + 1, "output rate", QT_TRANSLATE_NOOP("Refusal", "empty"));
    }
    return finishDecode(r, ctx, m);
}

void Rzb::writeJson(JsonWriter &w) const {
    w.beginObject().field("port", port).field("clear", entries.empty());
    w.key("messages").beginArray();
    for (const auto &e : entries)
        w.beginObject().field("address", e.address).field("rate", e.rate).endObject();
    w.endArray().endObject();
}

EncodeResult encodeRzb(std::optional<int> port, std::span<const RzbEntry> entries) {
    if (port)
        if (auto err = checkRange("PNVGRZB port", *port, 0, 3); !err.empty()) return refuse(err);
    if (entries.size() > kMaxOutputMessages)
        return refuse("PNVGRZB messages: " + std::to_string(entries.size()) +
                      " is out of range; accepted: 0.." + std::to_string(kMaxOutputMessages) +
                      " messages");
    std::string body = "PNVGRZB";
    if (port) body += ",PORT," + std::to_string(*port);
    for (const auto &e : entries) {
        bool valid = e.address.size() == 3 || e.address.size() == 7;
        for (char c : e.address)
            if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) valid = false;
        if (!valid)
            return refuse("PNVGRZB message address: '" + e.address +
                          "' must be 3 characters (GGA) or a 7-character proprietary address "
                          "(PNVGTST), upper-case letters and digits");
        if (e.rate < 1)
            return refuse("PNVGRZB " + e.address + " output rate: " + std::to_string(e.rate) +
                          " is out of range; accepted: >= 1 PVT intervals");
        body += "," + e.address + "," + std::to_string(e.rate);
    }
    return built(body);
}

} // namespace gnss::nvs
