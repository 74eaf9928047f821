// Output control: PNMRX103 (NMEA rates), PNMRX107 (Nemerix message modes), PNMRX108 (NMEA
// output sequence).
//
//   $PNMRX103,id,r,id,r,...*hh   id: GGA GLL GSA GSV RMC VTG ZDA ALL; r: 0..9 s (0 = skipped)
//   $PNMRX103, GSV, 2,GGA, 1,ZDA, 0*04    variable length
//   $PNMRX103, GSV, 2, GGA, 1, ZDA, 0,*28 fixed length (trailing comma)
//   $PNMRX107,code,mode,...*hh   code: 300..304 ALL; mode: 0 off, 1 now, 2 on change, 3 both
//   $PNMRX108,id,id,...*hh       the listed messages in this order, every second; others off
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

#include <array>

namespace gnss::nemerix {

const MessageType RateList::kNmeaType{"PNMRX103"};
const MessageType RateList::kNemerixType{"PNMRX107"};
const MessageType NmeaSequence::kType{"PNMRX108"};

namespace {

constexpr const auto &kNmeaIds = kNmeaMessageIds;
constexpr const auto &kNemerixIds = kNavDataMessageIds;

template <std::size_t N>
bool oneOf(std::string_view id, const std::array<std::string_view, N> &ids, bool allowAll) {
    if (allowAll && id == "ALL") return true;
    for (auto k : ids)
        if (k == id) return true;
    return false;
}

// One PNMRX103 (rate) or PNMRX107 (mode) pair, the id in field i.
void readRate(FieldReader &r, RateEntry &e, std::size_t i, bool nemerix) {
    e.id = r.text(i);
    const bool known = nemerix ? oneOf(e.id, kNemerixIds, true) : oneOf(e.id, kNmeaIds, true);
    if (!known) r.fail(i, "message id", QT_TRANSLATE_NOOP("Refusal", "unknown message"));
    e.value = r.integer(i + 1, nemerix ? "mode" : "rate");
    if (e.value && (*e.value < 0 || *e.value > (nemerix ? 3 : 9)))
        r.fail(i + 1, nemerix ? "mode" : "rate",
               nemerix ? QT_TRANSLATE_NOOP("Refusal", "not 0..3")
                       : QT_TRANSLATE_NOOP("Refusal", "not 0..9"));
}

bool decodeRates(const Sentence &s, DecodeContext &ctx, const MessageType &type, bool nemerix) {
    FieldReader r(s);
    RateList m(type);
    // The fixed-length form ends with an empty field.
    const std::size_t n =
            pairedFields(r, QT_TRANSLATE_NOOP("Refusal", "no message id given"),
                         QT_TRANSLATE_NOOP("Refusal", "message ids and values must come in pairs"));
    readPairs(r, n, m.entries, m.count, QT_TRANSLATE_NOOP("Refusal", "too many entries"),
              [&r, nemerix](RateEntry &e, std::size_t i) { readRate(r, e, i, nemerix); });
    return finishDecode(r, ctx, m);
}

const char *modeName(int mode) {
    switch (mode) {
    case 0: return "disabled";
    case 1: return "send now";
    case 2: return "send on change";
    case 3: return "send now and on change";
    default: return nullptr;
    }
}

} // namespace

bool decodeNmeaRates(const Sentence &s, DecodeContext &ctx) {
    return decodeRates(s, ctx, RateList::kNmeaType, false);
}
bool decodeNemerixRates(const Sentence &s, DecodeContext &ctx) {
    return decodeRates(s, ctx, RateList::kNemerixType, true);
}

void RateList::writeJson(JsonWriter &w) const {
    const bool nemerix = type == &kNemerixType;
    w.beginObject().key("entries").beginArray();
    for (std::size_t i = 0; i < count; ++i) {
        const auto &e = entries[i];
        w.beginObject().field(nemerix ? "message" : "id", e.id);
        if (nemerix) {
            w.field("mode", e.value).key("mode_name");
            if (const char *n = e.value ? modeName(*e.value) : nullptr)
                w.value(n);
            else
                w.null();
        } else {
            w.field("rate_s", e.value).field("enabled", e.value ? *e.value != 0 : false);
        }
        w.endObject();
    }
    w.endArray().endObject();
}

bool decodeNmeaSequence(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    NmeaSequence m;
    const std::size_t n = usedFields(r);
    if (n == 0) r.failSentence(std::string(QT_TRANSLATE_NOOP("Refusal", "no message id given")));
    for (std::size_t i = 0; r.ok() && i < n; ++i) {
        if (m.count == NmeaSequence::kMax) {
            r.failSentence(std::string(QT_TRANSLATE_NOOP("Refusal", "too many message ids")));
            break;
        }
        const auto id = r.text(i);
        if (!oneOf(id, kNmeaIds, false))
            r.fail(i, "message id", QT_TRANSLATE_NOOP("Refusal", "unknown message"));
        m.ids[m.count++] = id;
    }
    return finishDecode(r, ctx, m);
}

void NmeaSequence::writeJson(JsonWriter &w) const {
    w.beginObject().key("sequence").beginArray();
    for (std::size_t i = 0; i < count; ++i) w.value(ids[i]);
    w.endArray().endObject();
}

namespace {

EncodeResult encodeRates(std::span<const RateItem> items, bool nemerix, std::string_view prefix) {
    EncodeResult r;
    if (items.empty()) {
        r.error = nemerix ? "PNMRX107: no message given" : "PNMRX103: no message given";
        return r;
    }
    std::string fields;
    for (const auto &it : items) {
        const bool known = nemerix ? oneOf(it.id, kNemerixIds, true) : oneOf(it.id, kNmeaIds, true);
        if (!known) {
            r.error = "message id: '" + it.id + "' is not accepted; accepted: " +
                      (nemerix ? "300, 301, 302, 303, 304, ALL"
                               : "GGA, GLL, GSA, GSV, RMC, VTG, ZDA, ALL");
            return r;
        }
        const int max = nemerix ? 3 : 9;
        if (it.value < 0 || it.value > max) {
            r.error = (nemerix ? "mode of " : "rate of ") + it.id + ": " +
                      std::to_string(it.value) + " is out of range; accepted: 0.." +
                      std::to_string(max) + (nemerix ? "" : " s");
            return r;
        }
        fields += "," + it.id + "," + std::to_string(it.value);
    }
    return buildCommand(nemerix ? "107" : "103", fields, prefix);
}

} // namespace

EncodeResult encodeNmeaRates(std::span<const RateItem> items, std::string_view prefix) {
    return encodeRates(items, false, prefix);
}
EncodeResult encodeNemerixRates(std::span<const RateItem> items, std::string_view prefix) {
    return encodeRates(items, true, prefix);
}

EncodeResult encodeNmeaSequence(std::span<const std::string> ids, std::string_view prefix) {
    EncodeResult r;
    if (ids.empty()) {
        r.error = "sequence: no message given; accepted: GGA, GLL, GSA, GSV, RMC, VTG, ZDA";
        return r;
    }
    std::string fields;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!oneOf(std::string_view(ids[i]), kNmeaIds, false)) {
            r.error = "sequence: '" + ids[i] +
                      "' is not accepted; accepted: GGA, GLL, GSA, GSV, RMC, VTG, ZDA";
            return r;
        }
        for (std::size_t j = 0; j < i; ++j)
            if (ids[j] == ids[i]) {
                r.error = "sequence: " + ids[i] + " is listed twice";
                return r;
            }
        fields += "," + ids[i];
    }
    return buildCommand("108", fields, prefix);
}

} // namespace gnss::nemerix
