// 4.15 PNVGIDL: the list of known base stations (at most 32), command and replies.
//
//   $PNVGIDL,MODE,x*hh          0 any base station, 1 listed ones only   ($PNVGIDL,MODE,1*7C)
//   $PNVGIDL,ADD[,x[,x]]*hh     station id, GLONASS ICB; omitted = the current ones
//                               (reply: $PNVGIDL,ADD,0003,0.0720*3B)
//   $PNVGIDL,REMOVE,x*hh        reply $PNVGIDL,REMOVE,OK*4C
//   $PNVGIDL,CLEAR*hh           reply $PNVGIDL,CLEAR,OK*13
//   $PNVGIDL,SHOW*hh            reply: one item per station:
//   $PNVGIDL,x,x,xxxx,x.xxxx*hh 0 list length, 1 index (1-based), 2 station id, 3 ICB
#include "nvs/nvs_encode_util.h"
#include "nvs/nvs_output_fields.h"

#include "core/field_parse.h"

#include <cstdio>

namespace gnss::nvs {

const MessageType Idl::kType{"PNVGIDL"};

std::string_view toString(IdlKind k) {
    switch (k) {
    case IdlKind::Mode: return "mode";
    case IdlKind::Add: return "add";
    case IdlKind::Remove: return "remove";
    case IdlKind::Clear: return "clear";
    case IdlKind::Show: return "show";
    case IdlKind::Item: return "item";
    }
    return "show";
}

bool decodeIdl(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Idl>(s, ctx, 1, [&](FieldReader &r, Idl &m) {
        const auto sub = r.text(0);
        std::int64_t n;
        if (sub == "MODE") {
            m.kind = IdlKind::Mode;
            m.mode = r.integer(1, "mode");
        } else if (sub == "ADD") {
            m.kind = IdlKind::Add;
            m.stationId = r.integer(1, "station id");
            m.icb = r.real(2, "GLONASS ICB");
        } else if (sub == "REMOVE" || sub == "CLEAR") {
            m.kind = sub == "REMOVE" ? IdlKind::Remove : IdlKind::Clear;
            const auto f1 = r.text(1);
            if (!f1.empty() && !parseInt(f1, n)) { // a reply: "OK" (or the receiver's refusal)
                m.status = f1;
                m.ok = f1 == "OK";
            } else if (m.kind == IdlKind::Remove) {
                m.stationId = r.integer(1, "station id");
            }
        } else if (sub == "SHOW") {
            m.kind = IdlKind::Show;
        } else if (parseInt(sub, n)) {
            m.kind = IdlKind::Item;
            if (n == 0 && r.count() == 1) {
                m.count = 0; // "$PNVGIDL,0": the SHOW answer for an empty list
            } else if (r.require(4)) {
                m.count = r.integer(0, "list length");
                m.index = r.integer(1, "index");
                m.stationId = r.integer(2, "station id");
                m.icb = r.real(3, "GLONASS ICB");
            }
        } else {
            r.fail(0, "subcommand",
                   QT_TRANSLATE_NOOP("Refusal",
                                     "not MODE, ADD, REMOVE, CLEAR, SHOW or a list item"));
        }
    });
}

void Idl::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("kind", toString(kind))
            .field("mode", mode)
            .field("station_id", stationId)
            .field("icb", icb)
            .field("ok", ok)
            .field("status", status)
            .field("count", count)
            .field("index", index)
            .endObject();
}

namespace {
std::string stationText(int id) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04d", id);
    return buf;
}
std::string checkStation(int id) {
    return checkRange("PNVGIDL station ID", id, 0, kMaxStationId);
}

// A REMOVE/CLEAR reply word: a word, never a number (which would read as a station id).
bool isReplyWord(std::string_view w) {
    if (w.empty()) return false;
    for (char c : w)
        if (c < 'A' || c > 'Z') return false;
    return true;
}
} // namespace

EncodeResult encodeIdlMode(int mode) {
    if (auto err = checkSetting("idl.mode", std::to_string(mode)); !err.empty()) return refuse(err);
    return built("PNVGIDL,MODE," + std::to_string(mode));
}

EncodeResult encodeIdlAdd(std::optional<int> stationId, std::optional<double> icb) {
    if (icb && !stationId)
        return refuse(std::string("PNVGIDL ADD: a GLONASS ICB needs a station ID before it"));
    std::string body = "PNVGIDL,ADD";
    if (stationId) {
        if (auto err = checkStation(*stationId); !err.empty()) return refuse(err);
        body += "," + stationText(*stationId);
    }
    if (icb) {
        if (!(*icb >= -1.0 && *icb <= 1.0))
            return refuse("PNVGIDL GLONASS ICB: " + formatFixed(*icb, 4) +
                          " is out of range; accepted: -1..1 cycle");
        body += "," + formatFixed(*icb, 4);
    }
    return built(body);
}

EncodeResult encodeIdlRemove(int stationId) {
    if (auto err = checkStation(stationId); !err.empty()) return refuse(err);
    return built("PNVGIDL,REMOVE," + stationText(stationId));
}

EncodeResult encodeIdl(const Idl &m) {
    const std::string_view word = !m.status.empty() ? m.status : m.ok ? "OK" : "";
    OutputFields f(Idl::kType.name);
    switch (m.kind) {
    case IdlKind::Mode:
        if (m.mode) return encodeIdlMode(*m.mode);
        f.text("subcommand", "MODE");
        break;
    case IdlKind::Add: return encodeIdlAdd(m.stationId, m.icb);
    case IdlKind::Remove:
    case IdlKind::Clear:
        f.text("subcommand", m.kind == IdlKind::Remove ? "REMOVE" : "CLEAR");
        if (!word.empty()) { // the reply
            if (!isReplyWord(word))
                f.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not one of: %3"),
                                 {"PNVGIDL reply", std::string(word), "OK, ERROR"}));
            f.text("reply", word);
        } else if (m.kind == IdlKind::Remove && m.stationId) {
            return encodeIdlRemove(*m.stationId);
        }
        break;
    case IdlKind::Show: return encodeIdlShow();
    case IdlKind::Item:
        // "$PNVGIDL,0": SHOW's answer for an empty list; otherwise one item per station.
        if (m.count && *m.count == 0 && !m.index && !m.stationId && !m.icb)
            return built("PNVGIDL,0");
        if (!m.count)
            f.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected an integer, got '%2'"),
                             {"PNVGIDL list length", ""}));
        f.integer("list length", m.count, 1, kMaxStations)
                .integer("index", m.index, 1, m.count.value_or(kMaxStations))
                .integer("station ID", m.stationId, 0, kMaxStationId, 4)
                .real("GLONASS ICB", m.icb, 4, -1, 1);
        break;
    }
    return f.build();
}

EncodeResult encodeIdlClear() {
    return built("PNVGIDL,CLEAR");
}
EncodeResult encodeIdlShow() {
    return built("PNVGIDL,SHOW");
}

} // namespace gnss::nvs
