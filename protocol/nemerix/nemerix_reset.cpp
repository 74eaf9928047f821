// PNMRX111 (software reset) and PNMRX113 (stop GPS core activities).
//
//   $PNMRX111*68              reset per the configured fix procedure (PNMRX101/104)
//   $PNMRX111,bbb*hh          bit field 0..255: 0 reload settings from flash, 1 clear almanac,
//                             2 clear ephemeris, 3 clear iono/tropo corrections, 4 invalidate
//                             position, 5 invalidate time, 6 copy oscillator offset from
//                             settings, 7 sticky (repeat at every reset)
//   $PNMRX111,COLD*hh         FACTORY, COLD, WARM or HOT
//   $PNMRX113*6A              stops data extraction and fix generation until a reset
#include "core/field_parse.h"
#include "nemerix/nemerix_commands.h"

#include <algorithm>

namespace gnss::nemerix {

const MessageType SoftwareReset::kType{"PNMRX111"};
const MessageType PlainCommand::kStopCoreType{"PNMRX113"};

namespace {
constexpr const char *kBitNames[] = {
        "reload_settings",     "clear_almanac",   "clear_ephemeris",        "clear_iono_tropo",
        "invalidate_position", "invalidate_time", "copy_oscillator_offset", "sticky"};
constexpr std::string_view kNamed[] = {"FACTORY", "COLD", "WARM", "HOT"};

bool isNamed(std::string_view s) {
    return std::ranges::find(kNamed, s) != std::end(kNamed);
}
} // namespace

bool decodeSoftwareReset(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    SoftwareReset m;
    const auto t = r.text(0);
    if (!t.empty()) {
        std::int64_t v;
        if (parseInt(t, v)) {
            if (v < 0 || v > 255)
                r.fail(0, "invalidate parameter",
                       QT_TRANSLATE_NOOP("Refusal", "out of range 0..255"));
            else
                m.bits = static_cast<int>(v);
        } else if (isNamed(t)) {
            m.named = t;
        } else {
            r.fail(0, "invalidate parameter",
                   QT_TRANSLATE_NOOP("Refusal", "expected 0..255 or FACTORY/COLD/WARM/HOT"));
        }
    }
    return finishDecode(r, ctx, m);
}

void SoftwareReset::writeJson(JsonWriter &w) const {
    w.beginObject().field("bits", bits).key("named");
    if (named.empty())
        w.null();
    else
        w.value(named);
    w.key("actions").beginArray();
    if (bits)
        for (int b = 0; b < 8; ++b)
            if (*bits & (1 << b)) w.value(kBitNames[b]);
    w.endArray().endObject();
}

bool decodeStopCore(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    PlainCommand m(PlainCommand::kStopCoreType);
    return finishDecode(r, ctx, m);
}

EncodeResult encodeSoftwareReset(std::string_view action, std::string_view prefix) {
    EncodeResult r;
    if (action.empty()) return buildCommand("111", {}, prefix);
    std::int64_t v;
    if (parseInt(action, v)) {
        if (v < 0 || v > 255) {
            r.error = "reset: " + std::string(action) +
                      " is out of range; accepted: 0..255 (bit field) or FACTORY, COLD, WARM, HOT";
            return r;
        }
        return buildCommand("111", "," + std::to_string(v), prefix);
    }
    if (!isNamed(action)) {
        r.error = "reset: '" + std::string(action) +
                  "' is not accepted; accepted: 0..255 (bit field) or FACTORY, COLD, WARM, HOT";
        return r;
    }
    return buildCommand("111", "," + std::string(action), prefix);
}

} // namespace gnss::nemerix
