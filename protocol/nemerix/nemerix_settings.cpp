// Settings as commands: the commands the schema's rows name (core/settings_plan.h plans from
// them: each is sent once, in their order); nemerix_settings_values.cpp reads settings back from
// reports and commands. The order: PNMRX106 (datum), PNMRX110 (every fix mask in one sentence),
// PNMRX101 (channel count), PNMRX112 (power), PNMRX108 (sequence) before PNMRX103 (rates, which
// override the sequence's defaults), PNMRX107, and PNMRX100 last, since the port speed changes
// right after it.
#include "core/baud_rates.h"
#include "core/field_parse.h"
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_actions.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_dialect_parts.h"

#include <map>

namespace gnss::nemerix {

namespace {

struct Values {
    std::map<std::string, std::string> byKey; // canonical key → value
    bool has(const char *k) const { return byKey.count(k) != 0; }
    const std::string &get(const char *k) const { return byKey.at(k); }
    std::optional<int> integer(const char *k) const {
        std::int64_t v;
        if (!has(k) || !parseInt(get(k), v)) return std::nullopt;
        return static_cast<int>(v);
    }
    std::optional<double> real(const char *k) const {
        double v;
        if (!has(k) || !parseReal(get(k), v)) return std::nullopt;
        return v;
    }
};

struct MaskKey {
    const char *key;
    int id;
};
constexpr MaskKey kMaskKeys[] = {
        {"fix.timeZone", 0},   {"fix.maxPdop", 1},      {"fix.maxHdop", 2},      {"fix.maxVdop", 3},
        {"fix.minSnr", 4},     {"fix.minElevation", 5}, {"fix.noiseFloor", 6},   {"nav.mode", 7},
        {"fix.altitude2d", 8}, {"nav.dynamics", 9},     {"fix.maxAltitude", 10},
};

} // namespace

std::vector<std::string> sequenceIds(std::string_view list) {
    // Spaces around an id are the user's layout ("GGA; RMC"); one inside it is part of it, so
    // "G SV" is refused by name rather than sent as GSV.
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= list.size(); ++i)
        if (i == list.size() || list[i] == ';' || list[i] == ',') {
            const std::string_view id = Sentence::trim(list.substr(start, i - start));
            if (!id.empty()) out.emplace_back(id);
            start = i + 1;
        }
    return out;
}

const char *fixMaskKey(int id) {
    for (const auto &m : kMaskKeys)
        if (m.id == id) return m.key;
    return nullptr;
}

namespace {

Values valuesOf(std::span<const KeyValue> values) {
    Values v;
    for (const auto &kv : values) v.byKey[kv.key] = kv.value;
    return v;
}

// Writes only what `part` built; false when it refused (the refusal is in `out`).
EncodeResult withoutSentences(EncodeResult r) {
    if (!r.ok()) r.sentences.clear();
    return r;
}

// ---- The commands the schema's rows name ------------------------------------------------------

Refusal validateFix(const SettingDef &def, std::string_view value) {
    if (Refusal r = validateSetting(def, value); !r.empty()) return r;
    if (def.key != "fix.timeZone") return {};
    const std::string v(value);
    if (!parseTimeZone(v))
        return refusal(QT_TRANSLATE_NOOP("Refusal", "fix.timeZone: '%1' is not accepted; "
                                                    "accepted: h:m with hours -13..13 and "
                                                    "minutes 0..59"),
                       {v});
    // "-0:0" is UTC and reads back as "0:0": one way of writing it, so that what is applied is
    // what the receiver reports (the settings engine compares them).
    if (v.front() == '-' && *parseTimeZone(v) == 0)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "fix.timeZone: '%1' is UTC itself: write "
                                                    "0:0"),
                       {v});
    return {};
}

Refusal validateDatum(const SettingDef &def, std::string_view value) {
    if (Refusal r = validateSetting(def, value); !r.empty()) return r;
    std::int64_t d = 0;
    if (def.key == "datum.mapDatum" && parseInt(value, d) && d > 218 && d != 500)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "datum.mapDatum: %1 is out of range; "
                                                    "accepted: 0..218 (internal table) or 500 "
                                                    "(user defined)"),
                       {std::to_string(d)});
    return {};
}

// PNMRX106
EncodeResult writeDatum(std::span<const KeyValue> values) {
    const Values v = valuesOf(values);
    if (!v.has("datum.mapDatum")) {
        EncodeResult out;
        out.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "datum.mapDatum: required with any datum.* "
                                                        "setting; accepted: 0..218 or 500"),
                           {}));
        return out;
    }
    DatumParams p;
    p.correction = v.integer("datum.correction").value_or(0);
    p.datum = *v.integer("datum.mapDatum");
    p.dx = v.integer("datum.dx");
    p.dy = v.integer("datum.dy");
    p.dz = v.integer("datum.dz");
    p.inverseFlattening = v.real("datum.inverseFlattening");
    p.semiMajorAxis = v.real("datum.semiMajorAxis");
    return withoutSentences(encodeDatum(p));
}

// PNMRX110: every fix mask in one sentence.
EncodeResult writeFixMasks(std::span<const KeyValue> values) {
    const Values v = valuesOf(values);
    std::vector<FixMaskItem> masks;
    for (const auto &m : kMaskKeys)
        if (v.has(m.key)) masks.push_back({m.id, v.get(m.key)});
    return withoutSentences(encodeFixSettings(masks));
}

// PNMRX101
EncodeResult writeNavInit(std::span<const KeyValue> values) {
    NavInitParams p;
    p.channels = valuesOf(values).integer("nav.channels");
    return withoutSentences(encodeNavInit(p));
}

// PNMRX112
EncodeResult writePower(std::span<const KeyValue> values) {
    const Values v = valuesOf(values);
    const int mode = v.integer("power.mode").value_or(1);
    const auto off = v.integer("power.offPeriod");
    if (mode == 0 && off) {
        EncodeResult out;
        out.refuse(
                refusal(QT_TRANSLATE_NOOP("Refusal",
                                          "power.offPeriod: only used with power.mode=1 (LDCM1)"),
                        {}));
        return out;
    }
    return withoutSentences(encodePowerMode(mode, off));
}

// PNMRX108
EncodeResult writeSequence(std::span<const KeyValue> values) {
    EncodeResult r = withoutSentences(encodeNmeaSequence(sequenceIds(values.front().value)));
    if (!r.ok()) r.error = "output." + r.error;
    return r;
}

// The (id, value) items of PNMRX103 / PNMRX107 that `values` set, under "<prefix><id>", in the
// order of `ids`.
std::vector<RateItem> rateItems(std::span<const KeyValue> values, std::string_view prefix,
                                std::span<const std::string_view> ids) {
    const Values v = valuesOf(values);
    std::vector<RateItem> items;
    for (std::string_view id : ids) {
        const std::string key = std::string(prefix) + std::string(id);
        if (v.has(key.c_str())) items.push_back({std::string(id), *v.integer(key.c_str())});
    }
    return items;
}

// PNMRX103, after the sequence (its rates override the sequence's defaults).
EncodeResult writeRates(std::span<const KeyValue> values) {
    return withoutSentences(encodeNmeaRates(rateItems(values, "rate.", kNmeaMessageIds)));
}

// PNMRX107
EncodeResult writeNemerixRates(std::span<const KeyValue> values) {
    return withoutSentences(encodeNemerixRates(rateItems(values, "nmrx.", kNavDataMessageIds)));
}

// PNMRX100, last: the port's speed changes right after it.
EncodeResult writeSerial(std::span<const KeyValue> values) {
    const Values v = valuesOf(values);
    if (!v.has("serial.baud")) {
        EncodeResult out;
        out.refuse(
                refusal(QT_TRANSLATE_NOOP("Refusal",
                                          "serial.baud: required with serial.protocol / "
                                          "serial.parity (PNMRX100 sends all three); accepted: %1"),
                        {baudList(kSupportedBauds)}));
        return out;
    }
    return withoutSentences(encodeSerialPort(v.integer("serial.protocol").value_or(0),
                                             *v.integer("serial.baud"),
                                             v.integer("serial.parity").value_or(0)));
}

// One PNMRX603 request reports every readable setting (messages 0 to 4).
EncodeResult readSettingsReport(std::span<const std::string>) {
    EncodeResult out;
    out.sentences.push_back(buildSentence("PNMRX603"));
    return out;
}

} // namespace

const SettingCommand kDatumCommand{.name = "PNMRX106",
                                   .order = 0,
                                   .validate = validateDatum,
                                   .write = writeDatum,
                                   .read = readSettingsReport};
const SettingCommand kFixMaskCommand{.name = "PNMRX110",
                                     .order = 1,
                                     .validate = validateFix,
                                     .write = writeFixMasks,
                                     .read = readSettingsReport};
const SettingCommand kNavInitCommand{
        .name = "PNMRX101", .order = 2, .write = writeNavInit, .read = readSettingsReport};
const SettingCommand kPowerCommand{.name = "PNMRX112", .order = 3, .write = writePower};
const SettingCommand kSequenceCommand{.name = "PNMRX108", .order = 4, .write = writeSequence};
const SettingCommand kRatesCommand{
        .name = "PNMRX103", .order = 5, .write = writeRates, .read = readSettingsReport};
const SettingCommand kNemerixRatesCommand{
        .name = "PNMRX107", .order = 6, .write = writeNemerixRates};
const SettingCommand kSerialCommand{
        .name = "PNMRX100", .together = true, .changesLink = true, .write = writeSerial};

} // namespace gnss::nemerix
