// PNMRX600 (software version), PNMRX601 (ISP mode), PNMRX602 (flash content version).
//
//   $PNMRX600*6F        request (the spec prints *00, which is not its checksum)
//   $PNMRX600,...*hh    the receiver's report; the spec gives no field layout: kept as sent
//   $PNMRX601*6E        enter ISP (in-system programming) mode: the receiver leaves NMEA
//   $PNMRX602,...*hh    flash content version report, fields as sent
//
// encodeVersionReport writes a report's fields back as they were given.
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

namespace gnss::nemerix {

const MessageType PlainCommand::kIspType{"PNMRX601"};
const MessageType PlainCommand::kVersionQueryType{"PNMRX600 request"};
const MessageType VersionReport::kSoftwareType{"PNMRX600"};
const MessageType VersionReport::kFlashType{"PNMRX602"};

namespace {

bool hasFields(const Sentence &s) {
    return usedFields(FieldReader(s)) > 0;
}

bool decodeReport(const Sentence &s, DecodeContext &ctx, const MessageType &type) {
    FieldReader r(s);
    VersionReport m(type);
    readTexts(r, m.fieldsText, m.count);
    return finishDecode(r, ctx, m);
}

} // namespace

bool decodeSoftwareVersion(const Sentence &s, DecodeContext &ctx) {
    if (!hasFields(s)) {
        FieldReader r(s);
        PlainCommand m(PlainCommand::kVersionQueryType);
        return finishDecode(r, ctx, m);
    }
    return decodeReport(s, ctx, VersionReport::kSoftwareType);
}

bool decodeFlashVersion(const Sentence &s, DecodeContext &ctx) {
    return decodeReport(s, ctx, VersionReport::kFlashType);
}

bool decodeIsp(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    PlainCommand m(PlainCommand::kIspType);
    return finishDecode(r, ctx, m);
}

EncodeResult encodeVersionReport(const VersionReport &m, std::string_view prefix) {
    EncodeResult r;
    const bool flash = m.type == &VersionReport::kFlashType;
    bool any = false;
    std::string fields;
    for (std::size_t i = 0; i < m.count && i < VersionReport::kMax; ++i) {
        if (Refusal why = checkFieldText("version", m.fieldsText[i]); !why.empty()) {
            r.refuse(std::move(why));
            return r;
        }
        any = any || !m.fieldsText[i].empty();
        fields += ",";
        fields += m.fieldsText[i];
    }
    // A PNMRX600 without fields is the request, not a report.
    if (!any) {
        r.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: missing"), {"version"}));
        return r;
    }
    return buildCommand(flash ? "602" : "600", fields, prefix);
}

void PlainCommand::writeJson(JsonWriter &w) const {
    w.beginObject().field("command", type->name);
    const char *what = type == &kStopCoreType       ? "stop GPS core activities"
                       : type == &kIspType          ? "enter ISP mode"
                       : type == &kVersionQueryType ? "report software version"
                                                    : "report settings";
    w.field("meaning", what).endObject();
}

void VersionReport::writeJson(JsonWriter &w) const {
    std::string joined;
    for (std::size_t i = 0; i < count; ++i) {
        if (i) joined += ',';
        joined.append(fieldsText[i]);
    }
    w.beginObject().field("version", std::string_view(joined)).key("fields").beginArray();
    for (std::size_t i = 0; i < count; ++i) w.value(fieldsText[i]);
    w.endArray().endObject();
}

} // namespace gnss::nemerix
