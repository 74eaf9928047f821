// 4.7 PNVGTST: internal test results, sent at start-up or on request ($GPGPQ,PNVGTST*21).
//
//   $PNVGTST,sx,cx[,sx,cx]...*hh
//            name/result pairs: ID = device ID (decimal), ANT = antenna (0 active antenna
//            connected, 1 no antenna, 2 short circuit)
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

#include "core/field_parse.h"

namespace gnss::nvs {

const MessageType Tst::kType{"PNVGTST"};

bool decodeTst(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Tst>(s, ctx, 2, [&](FieldReader &r, Tst &m) {
        for (std::size_t i = 0; i < s.fieldCount(); i += 2) {
            const auto name = r.text(i);
            const auto result = r.text(i + 1);
            if (name.empty() && result.empty() && i + 1 >= s.fieldCount()) break;
            m.tests.push_back({name, result});
            if (name == "ID") m.deviceId = r.integer64(i + 1, "device ID");
            if (name == "ANT") m.antenna = r.integer(i + 1, "antenna test");
        }
    });
}

void Tst::writeJson(JsonWriter &w) const {
    w.beginObject().key("tests").beginArray();
    for (const auto &t : tests)
        w.beginObject().field("name", t.name).field("result", t.result).endObject();
    w.endArray();
    w.field("device_id", deviceId).field("antenna", antenna);
    std::string_view antennaText;
    if (antenna) {
        antennaText = *antenna == 0   ? "active antenna connected"
                      : *antenna == 1 ? "no antenna"
                      : *antenna == 2 ? "short circuit"
                                      : "unknown";
    }
    w.field("antenna_status", antennaText).endObject();
}

// The pairs as given (deviceId and antenna are what a decoder reads from them). The results
// of the two tests the spec names are checked: ID a decimal number, ANT 0, 1 or 2.
EncodeResult encodeTst(const Tst &m) {
    OutputFields f(Tst::kType.name);
    if (m.tests.empty())
        f.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: no test results"), {"PNVGTST"}));
    for (const TstItem &t : m.tests) {
        if (t.name.empty())
            f.refuse(
                    refusal(QT_TRANSLATE_NOOP("Refusal", "%1: a test result without its test name"),
                            {"PNVGTST"}));
        std::int64_t v = 0;
        if ((t.name == "ID" || t.name == "ANT") && !parseInt(t.result, v))
            f.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected an integer, got '%2'"),
                             {"PNVGTST " + std::string(t.name), std::string(t.result)}));
        else if (t.name == "ID" && v < 0)
            f.refuse(outOfRange("PNVGTST ID", std::string(t.result), ">= 0"));
        else if (t.name == "ANT" && (v < 0 || v > 2))
            f.refuse(outOfRange("PNVGTST ANT", std::string(t.result), "0..2"));
        f.text("test name", t.name).text("test result", t.result);
    }
    return f.build();
}

} // namespace gnss::nvs
