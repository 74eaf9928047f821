// $GPSGG: the GeoS-5 proprietary address (docs/spec-notes.md, "The GPSGG address": the
// spec misprints it as $GPGSGG, $GPGSSG and $GPGG; the checksums prove GPSGG). The first field
// names the message or command:
//
//   $GPSGG,RQUERY,<name>,...   reply (3.11)      $GPSGG,RQUERY   query (4.6)
//   $GPSGG,NQUERY,<port>,...   reply (3.12)      $GPSGG,NQUERY   query (4.7)
//   $GPSGG,JAMDET,             jamming detected (3.13; the trailing comma is part of it)
//   $GPSGG,<command>           any other input command of section 4 (CSTART, BDR115, GGA ON...)
#include "geostar/geostar_encode_util.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

namespace gnss::geostar {

const MessageType Jamdet::kType{"GPSGG,JAMDET"};
const MessageType Command::kType{"GPSGG command"};

bool decodeSgg(const Sentence &s, DecodeContext &ctx) {
    const std::string_view name = s.field(0);
    if (name == "RQUERY" && s.fieldCount() > 1) return decodeRquery(s, ctx);
    if (name == "NQUERY" && s.fieldCount() > 1) return decodeNquery(s, ctx);
    if (name == "JAMDET") return decodeJamdet(s, ctx);
    return decodeCommand(s, ctx);
}

bool decodeJamdet(const Sentence &s, DecodeContext &ctx) {
    // "$GPSGG,JAMDET,": one empty field after the name; anything else there is unexpected.
    for (std::size_t i = 1; i < s.fieldCount(); ++i) {
        if (!s.field(i).empty()) {
            ctx.fail(refusal(QT_TRANSLATE_NOOP("Refusal", "JAMDET: unexpected field %1"),
                             {std::to_string(i + 1)}));
            return false;
        }
    }
    ctx.deliver(Jamdet{});
    return true;
}

EncodeResult encodeJamdet(const Jamdet &) {
    return detail::sentence(std::string(kAddress) + ",JAMDET,");
}

void Jamdet::writeJson(JsonWriter &w) const {
    w.beginObject().field("jamming_detected", true).endObject();
}

bool decodeCommand(const Sentence &s, DecodeContext &ctx) {
    Command m;
    m.def = findCommand(s.field(0));
    if (!m.def) {
        ctx.fail(refusal(QT_TRANSLATE_NOOP("Refusal", "unknown GPSGG message or command '%1'"),
                         {std::string(s.field(0))}));
        return false;
    }
    if (s.fieldCount() > 1) {
        ctx.fail(refusal(QT_TRANSLATE_NOOP("Refusal", "GPSGG,%1 takes no parameters"),
                         {std::string(m.def->text)}));
        return false;
    }
    ctx.deliver(m);
    return true;
}

namespace {

std::string_view effectName(CommandEffect e) {
    switch (e) {
    case CommandEffect::None: return "none";
    case CommandEffect::ChangesBaud: return "changes_port_settings";
    case CommandEffect::ResetsReceiver: return "resets_receiver";
    case CommandEffect::ChangesProtocol: return "changes_protocol";
    case CommandEffect::ChangesOutput: return "changes_output";
    }
    return "none";
}

} // namespace

void Command::writeJson(JsonWriter &w) const {
    w.beginObject();
    if (!def) {
        w.endObject();
        return;
    }
    w.field("command", def->text).field("section", def->section);
    w.field("description", def->description);
    if (def->settingKey.empty())
        w.key("setting").null().key("value").null();
    else
        w.field("setting", def->settingKey).field("value", def->value);
    w.field("effect", effectName(def->effect));
    if (def->confirmedBy.empty())
        w.key("confirmed_by").null();
    else
        w.field("confirmed_by", def->confirmedBy);
    w.endObject();
}

} // namespace gnss::geostar
