// The commands the NVS schema's rows name (nvs_schema.cpp): how each group of settings is
// written and read back (core/settings_plan.h plans from them), and decoded replies back to
// KEY=VALUE pairs.
#include "nvs/nvs_encode_util.h"

#include "core/field_parse.h"
#include "core/sentence_builder.h"

#include <algorithm>
#include <array>
#include <map>

namespace gnss::nvs {

namespace {

std::string_view after(std::string_view key, std::string_view prefix) {
    return key.substr(0, prefix.size()) == prefix ? key.substr(prefix.size()) : std::string_view{};
}

std::vector<std::string_view> splitList(std::string_view v) {
    std::vector<std::string_view> out;
    while (!v.empty()) {
        const auto semi = v.find(';');
        auto item = v.substr(0, semi);
        while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
        if (!item.empty()) out.push_back(item);
        if (semi == std::string_view::npos) break;
        v.remove_prefix(semi + 1);
    }
    return out;
}

} // namespace

// "RMC:1;GSV:5" (a bare address means rate 1).
Refusal parseOutputList(std::string_view key, std::string_view v, std::vector<RzbEntry> &out) {
    for (auto item : splitList(v)) {
        const auto colon = item.find(':');
        std::int64_t rate = 1;
        if (colon != std::string_view::npos && !parseInt(item.substr(colon + 1), rate))
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not ADDRESS:RATE (rate in PVT "
                                                        "intervals, >= 1)"),
                           {std::string(key), std::string(item)});
        out.push_back({std::string(item.substr(0, colon)), static_cast<int>(rate)});
    }
    return {};
}

std::string formatOutputList(std::span<const RzbEntry> entries) {
    std::string v;
    for (const RzbEntry &e : entries)
        v += (v.empty() ? "" : ";") + e.address + ":" + std::to_string(e.rate);
    return v;
}

// "3:0.072;43" (a bare id adds the station with the current ICB).
Refusal parseStations(std::string_view v, std::vector<Station> &out) {
    for (auto item : splitList(v)) {
        const auto colon = item.find(':');
        std::int64_t id;
        double icb = 0;
        if (!parseInt(item.substr(0, colon), id) ||
            (colon != std::string_view::npos && !parseReal(item.substr(colon + 1), icb)))
            return refusal(QT_TRANSLATE_NOOP("Refusal", "idl.stations: '%1' is not ID:ICB"),
                           {std::string(item)});
        Station s{static_cast<int>(id), std::nullopt};
        if (colon != std::string_view::npos) s.icb = icb;
        // The receiver keeps a station once: a second ADD of it is no second entry, and the list
        // read back would not be the one sent.
        if (std::any_of(out.begin(), out.end(), [&](const Station &o) { return o.id == s.id; }))
            return refusal(QT_TRANSLATE_NOOP("Refusal", "idl.stations: station %1 is listed twice"),
                           {std::to_string(s.id)});
        out.push_back(s);
    }
    if (out.size() > kMaxStations)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "idl.stations: %1 stations is out of range; "
                                                    "accepted: 0..32 stations"),
                       {std::to_string(out.size())});
    return {};
}

std::string formatStations(std::span<const Station> stations) {
    std::string v;
    for (const Station &s : stations) {
        v += (v.empty() ? "" : ";") + std::to_string(s.id);
        if (s.icb) v += ":" + formatFixed(*s.icb, 4);
    }
    return v;
}

namespace {

// ---- The commands the schema's rows name (nvs_schema.h) ----------------------------------------

// The port a key names: "port.COM2.baud" → 2, "output.USB" → 3.
int portOfKey(std::string_view key) {
    key = key.substr(key.find('.') + 1);
    return portNumber(key.substr(0, key.find('.')));
}

std::int64_t integer(std::string_view v) {
    std::int64_t n = 0;
    parseInt(v, n);
    return n;
}

Refusal validateRtkRow(const SettingDef &def, std::string_view value) {
    return validateRtkValue(after(def.key, "rtk."), value);
}

EncodeResult writeRtk(std::span<const KeyValue> values) {
    std::vector<RtkSet> set;
    for (const auto &kv : values) set.push_back({std::string(after(kv.key, "rtk.")), kv.value});
    return encodeRtk(set);
}

EncodeResult readRtk(std::span<const std::string> keys) {
    std::vector<std::string> names;
    for (const auto &k : keys) names.emplace_back(after(k, "rtk."));
    return encodeRtk({}, names);
}

EncodeResult writeIdlMode(std::span<const KeyValue> values) {
    return encodeIdlMode(static_cast<int>(integer(values.front().value)));
}

Refusal validateStations(const SettingDef &, std::string_view value) {
    std::vector<Station> stations;
    return parseStations(value, stations);
}

// The list replaces the receiver's: CLEAR, then one ADD per station.
EncodeResult writeStations(std::span<const KeyValue> values) {
    std::vector<Station> stations;
    parseStations(values.front().value, stations);
    EncodeResult r = encodeIdlClear();
    for (const auto &st : stations) {
        EncodeResult add = encodeIdlAdd(st.id, st.icb);
        if (!add.ok()) return add;
        r.sentences.push_back(std::move(add.sentences.front()));
    }
    return r;
}

EncodeResult readStations(std::span<const std::string>) {
    return encodeIdlShow();
}

// Fields not given stay as they are (empty fields of PNVGPPS).
EncodeResult writePps(std::span<const KeyValue> values) {
    PpsSettings pps;
    for (const auto &kv : values) {
        const char c = kv.value.empty() ? '\0' : kv.value.front();
        const int n = static_cast<int>(integer(kv.value));
        const std::string_view f = after(kv.key, "pps.");
        if (f == "type") pps.type = c;
        if (f == "mode") pps.mode = c;
        if (f == "reference") pps.reference = c;
        if (f == "adjust") pps.adjust = n;
        if (f == "duration") pps.duration = n;
        if (f == "validity") pps.validity = c;
        if (f == "cable_delay") pps.cableDelay = n;
    }
    return encodePps(pps);
}

EncodeResult readPps(std::span<const std::string>) {
    return encodePps({});
}

EncodeResult writeNme(std::span<const KeyValue> values) {
    std::optional<int> f[3];
    constexpr std::string_view kKeys[] = {"nmea.time_decimals", "nmea.position_decimals",
                                          "nmea.talker_mode"};
    for (const auto &kv : values)
        for (int i = 0; i < 3; ++i)
            if (kv.key == kKeys[i]) f[i] = static_cast<int>(integer(kv.value));
    if (!f[0] || !f[1])
        return refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "PNVGNME sets time and position "
                                                           "decimals together: give %1 too"),
                              {std::string(f[0] ? kKeys[1] : kKeys[0])}));
    return encodeNme(*f[0], *f[1], f[2]);
}

Refusal validateOutput(const SettingDef &def, std::string_view value) {
    std::vector<RzbEntry> list;
    return parseOutputList(def.key, value, list);
}

// The list replaces the port's: a clear, then one add of every entry.
EncodeResult writeOutput(std::span<const KeyValue> values) {
    const KeyValue &kv = values.front();
    std::vector<RzbEntry> list;
    parseOutputList(kv.key, kv.value, list);
    const int port = portOfKey(kv.key);
    EncodeResult r = encodeRzb(port, {});
    if (!list.empty()) {
        EncodeResult add = encodeRzb(port, list);
        if (!add.ok()) return add;
        r.sentences.push_back(std::move(add.sentences.front()));
    }
    return r;
}

EncodeResult writePort(std::span<const KeyValue> values) {
    std::optional<int> baud, protocol;
    const int port = portOfKey(values.front().key);
    for (const auto &kv : values)
        (kv.key.ends_with(".baud") ? baud : protocol) = static_cast<int>(integer(kv.value));
    if (!baud || !protocol)
        return refuse(
                refusal(QT_TRANSLATE_NOOP("Refusal", "PNVGRZA sets baud rate and "
                                                     "protocol together: give %1 too"),
                        {"port." + std::string(portName(port)) + (baud ? ".protocol" : ".baud")}));
    return encodeRza(port, *baud, *protocol);
}

} // namespace

// In the safe order: RTK engine, base stations, time pulse, NMEA format, output lists, and the
// ports last (they switch the link the rest travels on).
const SettingCommand kRtkCommand{.name = "PNVGRTK",
                                 .order = 0,
                                 .validate = validateRtkRow,
                                 .write = writeRtk,
                                 .read = readRtk};
const SettingCommand kIdlModeCommand{.name = "PNVGIDL,MODE", .order = 1, .write = writeIdlMode};
const SettingCommand kStationsCommand{.name = "PNVGIDL,ADD",
                                      .order = 2,
                                      .validate = validateStations,
                                      .write = writeStations,
                                      .read = readStations};
const SettingCommand kPpsCommand{.name = "PNVGPPS", .order = 3, .write = writePps, .read = readPps};
const SettingCommand kNmeCommand{
        .name = "PNVGNME", .together = true, .order = 4, .write = writeNme};
const SettingCommand kOutputCommands[3] = {
        {.name = "PNVGRZB,1", .order = 5, .validate = validateOutput, .write = writeOutput},
        {.name = "PNVGRZB,2", .order = 5, .validate = validateOutput, .write = writeOutput},
        {.name = "PNVGRZB,3", .order = 5, .validate = validateOutput, .write = writeOutput},
};
const SettingCommand kPortCommands[3] = {
        {.name = "PNVGRZA,1", .together = true, .changesLink = true, .write = writePort},
        {.name = "PNVGRZA,2", .together = true, .changesLink = true, .write = writePort},
        {.name = "PNVGRZA,3", .together = true, .changesLink = true, .write = writePort},
};

void extractSettings(const Message &reply, std::vector<KeyValue> &out) {
    if (const auto *rtk = message_cast<Rtk>(reply)) {
        for (const auto &p : rtk->params) {
            if (p.values.empty() || !isRtkParameter(p.name)) continue;
            std::string v;
            for (auto x : p.values) v += (v.empty() ? "" : ",") + std::string(x);
            out.push_back({"rtk." + std::string(p.name), v});
        }
    } else if (const auto *pps = message_cast<Pps>(reply)) {
        auto put = [&](const char *key, auto value) {
            if (!value) return;
            if constexpr (std::is_same_v<std::decay_t<decltype(*value)>, char>)
                out.push_back({key, std::string(1, *value)});
            else
                out.push_back({key, std::to_string(*value)});
        };
        put("pps.type", pps->type);
        put("pps.mode", pps->mode);
        put("pps.reference", pps->reference);
        put("pps.adjust", pps->adjust);
        put("pps.duration", pps->duration);
        put("pps.validity", pps->validity);
        put("pps.cable_delay", pps->cableDelay);
    } else if (const auto *nme = message_cast<Nme>(reply)) {
        if (nme->timeDecimals)
            out.push_back({"nmea.time_decimals", std::to_string(*nme->timeDecimals)});
        if (nme->positionDecimals)
            out.push_back({"nmea.position_decimals", std::to_string(*nme->positionDecimals)});
        if (nme->talkerMode) out.push_back({"nmea.talker_mode", std::to_string(*nme->talkerMode)});
    } else if (const auto *rza = message_cast<Rza>(reply)) {
        const auto name = portName(rza->port.value_or(0));
        if (rza->port && *rza->port >= 1 && *rza->port <= 3) {
            const std::string prefix = "port." + std::string(name);
            if (rza->baud) out.push_back({prefix + ".baud", std::to_string(*rza->baud)});
            if (rza->protocol)
                out.push_back({prefix + ".protocol", std::to_string(*rza->protocol)});
        }
    } else if (const auto *idl = message_cast<Idl>(reply)) {
        if (idl->kind == IdlKind::Mode && idl->mode)
            out.push_back({"idl.mode", std::to_string(*idl->mode)});
        // One station per SHOW item: a reader joins the items of one reply with ';'.
        if (idl->kind == IdlKind::Item && idl->stationId && idl->icb) {
            const Station one[] = {{*idl->stationId, idl->icb}};
            out.push_back({"idl.stations", formatStations(one)});
        }
    }
}

} // namespace gnss::nvs
