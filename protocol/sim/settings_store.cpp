#include "sim/settings_store.h"

#include "core/field_parse.h"
#include "core/settings_plan.h"

namespace gnss::sim {

SettingsStore::SettingsStore(const Dialect &dialect) : dialect_(dialect) {
    for (const SettingDef &def : dialect.settings)
        defaults_[std::string(def.key)] = std::string(def.defaultValue);
    current_ = saved_ = defaults_;
}

const std::string &SettingsStore::value(std::string_view key) const {
    static const std::string kNone;
    const auto it = current_.find(key);
    return it == current_.end() ? kNone : it->second;
}

long long SettingsStore::integer(std::string_view key, long long fallback) const {
    std::int64_t v = 0;
    return parseInt(value(key), v) ? v : fallback;
}

double SettingsStore::real(std::string_view key, double fallback) const {
    double v = 0;
    return parseReal(value(key), v) ? v : fallback;
}

bool SettingsStore::set(std::string_view key, std::string v) {
    const SettingDef *def = findSetting(dialect_.settings, key);
    if (!def) return false;
    const Refusal why = def->command && def->command->validate ? def->command->validate(*def, v)
                                                               : validateSetting(*def, v);
    if (!why.empty()) return false;
    current_[std::string(def->key)] = std::move(v);
    return true;
}

void SettingsStore::seed(std::string_view key, std::string v) {
    defaults_[std::string(key)] = v;
    current_[std::string(key)] = v;
    saved_[std::string(key)] = std::move(v);
}

std::vector<std::string> SettingsStore::apply(const Message &command) {
    std::vector<std::string> changed;
    if (!dialect_.extractSettings) return changed;
    std::vector<KeyValue> carried;
    dialect_.extractSettings(command, carried);
    for (KeyValue &kv : carried) {
        const std::string before = value(kv.key);
        if (set(kv.key, kv.value) && value(kv.key) != before) changed.push_back(kv.key);
    }
    return changed;
}

EncodeResult SettingsStore::report(std::span<const std::string> keys) const {
    std::vector<KeyValue> values;
    for (const std::string &k : keys) values.push_back({k, value(k)});
    // Each command's own sentences only: no confirming read (the receiver is the one answering).
    std::vector<PlannedCommand> plan;
    EncodeResult result;
    if (Refusal why = planWrites(dialect_, values, plan); !why.empty()) {
        result.refuse(std::move(why));
        return result;
    }
    for (const PlannedCommand &p : plan) {
        EncodeResult part = p.command->write(p.values);
        if (!part.ok()) return part;
        for (auto &s : part.sentences) result.sentences.push_back(std::move(s));
    }
    return result;
}

} // namespace gnss::sim
