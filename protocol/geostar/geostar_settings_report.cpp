// The settings RQUERY (3.11) and NQUERY (3.12) report, both ways: read from a decoded reply or
// set command (extractSettings: the settings engine's read-back, the simulator's store) and
// written into a reply (reportSettings: the simulator's answers). One table per mapping, so the
// two directions cannot disagree.
#include "geostar/geostar_messages.h"
#include "geostar/geostar_schema.h"

namespace gnss::geostar {
namespace {

// nav.DAT ↔ configuration register 2 bits 15:14 (table 9).
struct DatumCode {
    std::string_view value;
    int code;
};
constexpr DatumCode kDatums[] = {{"W84", 0}, {"P90", 1}, {"999", 2}};

// nav.NVS ↔ configuration register 1 bits 2:0 (table 8: Galileo, GPS, GLONASS in use).
struct Systems {
    std::string_view value;
    bool galileo, gps, glonass;
};
constexpr Systems kSystems[] = {
        {"MIX", true, true, true}, {"GPS", false, true, false}, {"GLN", false, false, true}};

// Actions (restarts, save, binary protocol) are rows of the schema too, but set nothing a
// reply reports.
bool isAction(std::string_view key) {
    return key.starts_with("action.");
}

// The value of `key` in `values`, checked against its schema row; nullptr when absent.
const std::string *valueOf(const SettingValues &values, std::string_view key, Refusal &why) {
    const auto it = values.find(key);
    if (it == values.end() || !why.empty()) return nullptr;
    if (const SettingDef *def = findSetting(settingsSchema(), key))
        why = validateSetting(*def, it->second);
    return why.empty() ? &it->second : nullptr;
}

} // namespace

void extractSettings(const Message &message, std::vector<KeyValue> &out) {
    if (const auto *n = message_cast<Nquery>(message)) {
        if (n->rateCode && rateCodeToHz(*n->rateCode))
            out.push_back({"output.RATE", std::to_string(rateCodeToHz(*n->rateCode))});
        if (n->nmeaVersion == 2 || n->nmeaVersion == 4)
            out.push_back({"output.NMEAV", std::to_string(*n->nmeaVersion)});
        for (std::size_t i = 0; i < n->codeCount; ++i) {
            if (Nquery::kNames[i].empty() || !n->codes[i]) continue;
            out.push_back(
                    {"output." + std::string(Nquery::kNames[i]), n->codes[i] == '0' ? "0" : "1"});
        }
        return;
    }
    if (const auto *q = message_cast<Rquery>(message)) {
        const ConfigRegister1 &c1 = q->config1;
        if (c1.rateHz) out.push_back({"output.RATE", std::to_string(c1.rateHz)});
        out.push_back({"power.PSM", c1.powerSavingEnabled ? "1" : "0"});
        for (const DatumCode &d : kDatums)
            if (d.code == q->config2.datumCode) out.push_back({"nav.DAT", std::string(d.value)});
        for (const Systems &s : kSystems)
            if (s.galileo == c1.galileo && s.gps == c1.gps && s.glonass == c1.glonass)
                out.push_back({"nav.NVS", std::string(s.value)});
        return;
    }
    if (const auto *c = message_cast<Command>(message)) {
        if (c->def && !c->def->settingKey.empty() && !isAction(c->def->settingKey))
            out.push_back({std::string(c->def->settingKey), std::string(c->def->value)});
    }
}

Refusal reportSettings(const SettingValues &values, Rquery &reply) {
    Rquery r = reply;
    Refusal why;
    if (const std::string *v = valueOf(values, "output.RATE", why)) {
        r.config1.rateHz = std::stoi(*v);
        r.config1.rateCode = rateHzToCode(r.config1.rateHz);
    }
    if (const std::string *v = valueOf(values, "power.PSM", why))
        r.config1.powerSavingEnabled = *v == "1";
    if (const std::string *v = valueOf(values, "nav.NVS", why))
        for (const Systems &s : kSystems)
            if (s.value == *v) {
                r.config1.galileo = s.galileo;
                r.config1.gps = s.gps;
                r.config1.glonass = s.glonass;
            }
    if (const std::string *v = valueOf(values, "nav.DAT", why))
        for (const DatumCode &d : kDatums)
            if (d.value == *v) r.config2.datumCode = d.code;
    if (why.empty()) reply = r;
    return why;
}

Refusal reportSettings(const SettingValues &values, Nquery &reply) {
    Nquery n = reply;
    Refusal why;
    if (const std::string *v = valueOf(values, "output.RATE", why))
        n.rateCode = rateHzToCode(std::stoi(*v));
    if (const std::string *v = valueOf(values, "output.NMEAV", why)) n.nmeaVersion = std::stoi(*v);
    for (std::size_t i = 0; i < Nquery::kMessages; ++i) {
        if (Nquery::kNames[i].empty()) continue;
        const std::string *v = valueOf(values, "output." + std::string(Nquery::kNames[i]), why);
        if (!v) continue;
        char &code = n.codes[i];
        if (*v == "0")
            code = '0';
        else if (!code || code == '0')
            code = 'R';
        n.codeCount = std::max(n.codeCount, i + 1);
    }
    if (why.empty()) reply = n;
    return why;
}

} // namespace gnss::geostar
