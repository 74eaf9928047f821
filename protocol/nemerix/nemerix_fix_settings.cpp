// PNMRX110: fix settings, as (mask id, value) pairs.
//
//   $PNMRX110,id,value,id,value,...*hh
//   id 0  local time zone   h:m (hours -13..13, minutes 0..59)   $PNMRX110, 0,-2:0*6C
//      1  maximum PDOP      x10, 0..100
//      2  maximum HDOP      x10, 0..100
//      3  maximum VDOP      x10, 0..100
//      4  minimum SNR       dB-Hz, 20..45                        $PNMRX110, 4, 35*5B
//      5  minimum elevation degrees, 0..90
//      6  noise floor       400..1000
//      7  navigation mode 1 1 auto (hold altitude), 2 2D, 4 3D (compute altitude)
//      8  2D mode altitude  metres above MSL, up to 6 digits
//      9  navigation mode 2 0 auto, 1 static
//     10  maximum altitude  metres, up to 6 digits
#include "core/field_parse.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

#include <cmath>

namespace gnss::nemerix {

const MessageType FixSettings::kType{"PNMRX110"};

namespace {

struct MaskDef {
    const char *name;
    int min, max; // range of the value as sent
    int divisor;  // engineering value = sent / divisor
    const char *unit;
};

constexpr MaskDef kMasks[] = {
        {"local_time_zone", 0, 0, 1, "h:m"}, {"max_pdop", 0, 100, 10, ""},
        {"max_hdop", 0, 100, 10, ""},        {"max_vdop", 0, 100, 10, ""},
        {"min_snr", 20, 45, 1, "dB-Hz"},     {"min_elevation", 0, 90, 1, "deg"},
        {"noise_floor", 400, 1000, 1, ""},   {"navigation_mode_1", 1, 4, 1, ""},
        {"altitude_2d", 0, 999999, 1, "m"},  {"navigation_mode_2", 0, 1, 1, ""},
        {"max_altitude", 0, 999999, 1, "m"},
};
constexpr int kMaskCount = static_cast<int>(sizeof kMasks / sizeof kMasks[0]);

bool validValue(int id, std::int64_t v) {
    const MaskDef &d = kMasks[id];
    if (v < d.min || v > d.max) return false;
    if (id == 7) return v == 1 || v == 2 || v == 4;
    return true;
}

std::string acceptedText(int id) {
    const MaskDef &d = kMasks[id];
    if (id == 0) return "h:m with hours -13..13 and minutes 0..59";
    if (id == 7) return "1 (auto), 2 (2D), 4 (3D)";
    if (id == 9) return "0 (auto), 1 (static)";
    if (d.divisor == 10) return "0..10 (sent x10)";
    std::string s = std::to_string(d.min) + ".." + std::to_string(d.max);
    if (*d.unit) s += std::string(" ") + d.unit;
    return s;
}

} // namespace

const char *fixMaskName(int id) {
    return id >= 0 && id < kMaskCount ? kMasks[id].name : nullptr;
}

std::optional<int> parseTimeZone(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    std::string_view h = text.substr(0, colon), m = text.substr(colon + 1);
    const bool negative = !h.empty() && h.front() == '-';
    std::int64_t hv, mv;
    if (!parseInt(h, hv) || !parseInt(m, mv)) return std::nullopt;
    if (hv < -13 || hv > 13 || mv < 0 || mv > 59 || (!m.empty() && m.front() == '-'))
        return std::nullopt;
    const int total = static_cast<int>(std::abs(hv) * 60 + mv);
    return negative ? -total : total;
}

namespace {
// One PNMRX110 pair, the id in field i; a problem ends the list (the reader is failed).
void readMask(FieldReader &r, FixMask &f, std::size_t i) {
    const auto id = r.integer(i, "mask id");
    if (!id) {
        if (r.ok()) r.fail(i, "mask id", QT_TRANSLATE_NOOP("Refusal", "missing"));
        return;
    }
    if (*id < 0 || *id >= kMaskCount) {
        r.fail(i, "mask id", QT_TRANSLATE_NOOP("Refusal", "unknown mask (0..10)"));
        return;
    }
    f.id = *id;
    f.text = r.text(i + 1);
    if (f.id == 0) {
        f.tzMinutes = parseTimeZone(f.text);
        if (!f.tzMinutes)
            r.fail(i + 1, "local time zone", QT_TRANSLATE_NOOP("Refusal", "expected h:m"));
        return;
    }
    const auto v = r.integer64(i + 1, kMasks[f.id].name);
    if (!v) {
        if (r.ok()) r.fail(i + 1, kMasks[f.id].name, QT_TRANSLATE_NOOP("Refusal", "missing"));
        return;
    }
    if (!validValue(f.id, *v))
        r.fail(i + 1, kMasks[f.id].name, QT_TRANSLATE_NOOP("Refusal", "out of range"));
    f.value = static_cast<double>(*v) / kMasks[f.id].divisor;
}
} // namespace

bool decodeFixSettings(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    FixSettings m;
    const std::size_t n =
            pairedFields(r, QT_TRANSLATE_NOOP("Refusal", "no mask given"),
                         QT_TRANSLATE_NOOP("Refusal", "mask ids and values must come in pairs"));
    readPairs(r, n, m.masks, m.count, QT_TRANSLATE_NOOP("Refusal", "too many masks"),
              [&r](FixMask &f, std::size_t i) { readMask(r, f, i); });
    return finishDecode(r, ctx, m);
}

void FixSettings::writeJson(JsonWriter &w) const {
    w.beginObject().key("masks").beginArray();
    for (std::size_t i = 0; i < count; ++i) {
        const FixMask &f = masks[i];
        w.beginObject().field("id", f.id).field("name", fixMaskName(f.id)).field("text", f.text);
        if (f.id == 0)
            w.field("tz_minutes", f.tzMinutes);
        else
            w.field("value", f.value);
        w.endObject();
    }
    w.endArray().endObject();
}

EncodeResult encodeFixSettings(std::span<const FixMaskItem> masks, std::string_view prefix) {
    EncodeResult r;
    if (masks.empty()) {
        r.error = "PNMRX110: no mask given";
        return r;
    }
    std::string fields;
    for (const auto &m : masks) {
        if (m.id < 0 || m.id >= kMaskCount) {
            r.error = "mask id: " + std::to_string(m.id) + " is out of range; accepted: 0..10";
            return r;
        }
        const std::string name = kMasks[m.id].name;
        std::string text;
        if (m.id == 0) {
            const auto tz = parseTimeZone(m.value);
            if (!tz) {
                r.error =
                        name + ": '" + m.value + "' is not accepted; accepted: " + acceptedText(0);
                return r;
            }
            const int a = std::abs(*tz);
            text = (*tz < 0 ? "-" : "") + std::to_string(a / 60) + ":" + std::to_string(a % 60);
        } else {
            double v;
            if (!parseReal(m.value, v)) {
                r.error = name + ": '" + m.value +
                          "' is not a number; accepted: " + acceptedText(m.id);
                return r;
            }
            const double sent = v * kMasks[m.id].divisor;
            const long long iv = std::llround(sent);
            if (std::fabs(sent - static_cast<double>(iv)) > 1e-6 || !validValue(m.id, iv)) {
                r.error =
                        name + ": " + m.value + " is out of range; accepted: " + acceptedText(m.id);
                return r;
            }
            text = std::to_string(iv);
        }
        fields += "," + std::to_string(m.id) + "," + text;
    }
    return buildCommand("110", fields, prefix);
}

} // namespace gnss::nemerix
