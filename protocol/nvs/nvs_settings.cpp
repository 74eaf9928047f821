// The dialect's generic settings functions over the schema (nvs_schema.cpp): KEY=VALUE pairs to
// sentences, keys to read-back queries, and decoded replies back to KEY=VALUE pairs.
//
// encodeSettings validates everything first and builds nothing on error. Sentences come in a
// safe order: RTK engine, base station list, time pulse, NMEA format, output lists, and port
// settings last (they switch the link the rest travels on).
#include "nvs_encode_util.h"

#include "core/field_parse.h"
#include "core/sentence_builder.h"

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

// "3:0.072;43" (a bare id adds the station with the current ICB).
struct Station {
    int id;
    std::optional<double> icb;
};
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
        out.push_back(s);
    }
    if (out.size() > 32)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "idl.stations: %1 stations is out of range; "
                                                    "accepted: 0..32 stations"),
                       {std::to_string(out.size())});
    return {};
}

} // namespace

EncodeResult encodeSettings(std::span<const KeyValue> values) {
    std::vector<RtkSet> rtk;
    std::optional<int> idlMode;
    std::optional<std::vector<Station>> stations;
    PpsSettings pps;
    bool anyPps = false;
    std::optional<int> nme[3];
    std::map<int, std::vector<RzbEntry>> outputs;
    std::map<int, std::pair<std::optional<int>, std::optional<int>>> ports; // baud, protocol

    for (const auto &kv : values) {
        const SettingDef *def = findSetting(settingsSchema(), kv.key);
        if (!def)
            return refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "unknown setting '%1' (gnss-cli "
                                                               "schema nvs lists them)"),
                                  {kv.key}));
        const std::string_view key = def->key;
        const std::string &v = kv.value;
        Refusal err;
        if (auto name = after(key, "rtk."); !name.empty()) {
            err = validateRtkValue(name, v);
            rtk.push_back({std::string(name), v});
        } else if (auto out = after(key, "output."); !out.empty()) {
            std::vector<RzbEntry> list;
            err = parseOutputList(key, v, list);
            outputs[portNumber(out)] = std::move(list);
        } else if (key == "idl.stations") {
            stations.emplace();
            err = parseStations(v, *stations);
        } else {
            err = validateSetting(*def, v);
            if (err.empty()) {
                std::int64_t n = 0;
                parseInt(v, n);
                const char c = v.empty() ? '\0' : v.front();
                if (key == "idl.mode")
                    idlMode = static_cast<int>(n);
                else if (key == "nmea.time_decimals")
                    nme[0] = static_cast<int>(n);
                else if (key == "nmea.position_decimals")
                    nme[1] = static_cast<int>(n);
                else if (key == "nmea.talker_mode")
                    nme[2] = static_cast<int>(n);
                else if (auto port = after(key, "port."); !port.empty()) {
                    const auto dot = port.find('.');
                    auto &slot = ports[portNumber(port.substr(0, dot))];
                    (port.substr(dot + 1) == "baud" ? slot.first : slot.second) =
                            static_cast<int>(n);
                } else if (after(key, "pps.").size()) {
                    anyPps = true;
                    if (key == "pps.type")
                        pps.type = c;
                    else if (key == "pps.mode")
                        pps.mode = c;
                    else if (key == "pps.reference")
                        pps.reference = c;
                    else if (key == "pps.adjust")
                        pps.adjust = static_cast<int>(n);
                    else if (key == "pps.duration")
                        pps.duration = static_cast<int>(n);
                    else if (key == "pps.validity")
                        pps.validity = c;
                    else if (key == "pps.cable_delay")
                        pps.cableDelay = static_cast<int>(n);
                }
            }
        }
        if (!err.empty()) return refuse(err);
    }
    if ((nme[0] || nme[1] || nme[2]) && !(nme[0] && nme[1]))
        return refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "PNVGNME sets time and position "
                                                           "decimals together: give %1 too"),
                              {nme[0] ? "nmea.position_decimals" : "nmea.time_decimals"}));
    for (const auto &[port, slot] : ports)
        if (!slot.first || !slot.second)
            return refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "PNVGRZA sets baud rate and "
                                                               "protocol together: give %1 too"),
                                  {"port." + std::string(portName(port)) +
                                   (slot.first ? ".protocol" : ".baud")}));

    // Everything is valid: build, in the safe order.
    EncodeResult result;
    auto add = [&](EncodeResult r) {
        if (!r.ok() && result.error.empty())
            result.refuse(r.refusal.text == r.error ? r.refusal : Refusal(r.error));
        for (auto &s : r.sentences) result.sentences.push_back(std::move(s));
    };
    if (!rtk.empty()) add(encodeRtk(rtk));
    if (idlMode) add(encodeIdlMode(*idlMode));
    if (stations) {
        add(encodeIdlClear());
        for (const auto &s : *stations) add(encodeIdlAdd(s.id, s.icb));
    }
    if (anyPps) add(encodePps(pps));
    if (nme[0]) add(encodeNme(*nme[0], *nme[1], nme[2]));
    for (const auto &[port, list] : outputs) {
        add(encodeRzb(port, {}));
        if (!list.empty()) add(encodeRzb(port, list));
    }
    for (const auto &[port, slot] : ports) add(encodeRza(port, *slot.first, *slot.second));
    if (!result.error.empty()) result.sentences.clear();
    return result;
}

EncodeResult encodeQueries(std::span<const std::string> keys) {
    std::vector<std::string> rtk;
    bool pps = false, stations = false;
    for (const auto &k : keys) {
        const SettingDef *def = findSetting(settingsSchema(), k);
        if (!def) return refuse("unknown setting '" + k + "' (gnss-cli schema nvs lists them)");
        if (def->access == SettingAccess::WriteOnly)
            return refuse(std::string(def->key) +
                          " is write-only: the spec documents no way to read it back");
        if (auto name = after(def->key, "rtk."); !name.empty()) {
            bool dup = false;
            for (const auto &n : rtk) dup = dup || n == name;
            if (!dup) rtk.emplace_back(name);
        } else if (!after(def->key, "pps.").empty()) {
            pps = true;
        } else if (def->key == "idl.stations") {
            stations = true;
        }
    }
    EncodeResult result;
    auto add = [&](EncodeResult r) {
        for (auto &s : r.sentences) result.sentences.push_back(std::move(s));
    };
    if (!rtk.empty()) add(encodeRtk({}, rtk));
    if (pps) add(encodePps({}));
    if (stations) add(encodeIdlShow());
    return result;
}

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
        if (idl->kind == IdlKind::Item && idl->stationId && idl->icb)
            out.push_back({"idl.stations",
                           std::to_string(*idl->stationId) + ":" + formatFixed(*idl->icb, 4)});
    }
}

} // namespace gnss::nvs
