#include "core/settings_plan.h"

#include "core/dialect.h"

#include <algorithm>

namespace gnss {
namespace {

// Commands that change the link last, then by order; the plan is built in the order the
// settings were given, which the stable sort keeps among equals.
void sortByPlan(std::vector<PlannedCommand> &plan) {
    std::stable_sort(plan.begin(), plan.end(),
                     [](const PlannedCommand &a, const PlannedCommand &b) {
                         return std::pair(a.command->changesLink, a.command->order) <
                                std::pair(b.command->changesLink, b.command->order);
                     });
}

// The read that confirms a command's writes: of the readable settings written.
EncodeResult confirmingRead(const PlannedCommand &p) {
    std::vector<std::string> keys;
    for (const KeyValue &kv : p.values) keys.push_back(kv.key);
    return p.command->read(keys);
}

PlannedCommand &groupOf(std::vector<PlannedCommand> &plan, const SettingCommand *c) {
    for (auto &p : plan)
        if (p.command == c) return p;
    plan.push_back({c, {}});
    return plan.back();
}

void appendOnce(std::vector<std::string> &to, std::vector<std::string> &&from) {
    for (auto &s : from)
        if (std::find(to.begin(), to.end(), s) == to.end()) to.push_back(std::move(s));
}

} // namespace

Refusal unknownSetting(const Dialect &d, std::string_view key) {
    const SettingKeyHint hint = settingKeyHint(d.settings, key);
    if (hint.ambiguous)
        return refusal(QT_TRANSLATE_NOOP("Refusal", "'%1' names several settings of the %2 "
                                                    "dialect: %3"),
                       {std::string(key), std::string(d.id), hint.list()});
    if (!hint.keys.empty())
        return refusal(QT_TRANSLATE_NOOP("Refusal", "unknown setting '%1' of the %2 dialect: did "
                                                    "you mean %3?"),
                       {std::string(key), std::string(d.id), hint.list()});
    return refusal(QT_TRANSLATE_NOOP("Refusal", "unknown setting '%1' of the %2 dialect (gnss-cli "
                                                "schema %2 lists them)"),
                   {std::string(key), std::string(d.id)});
}

Refusal planWrites(const Dialect &d, std::span<const KeyValue> values,
                   std::vector<PlannedCommand> &out) {
    out.clear();
    if (values.empty()) return Refusal("no setting given");
    for (const KeyValue &kv : values) {
        const SettingDef *def = findSetting(d.settings, kv.key);
        if (!def) return unknownSetting(d, kv.key);
        if (def->access == SettingAccess::ReadOnly || !def->command || !def->command->write)
            return refusal(QT_TRANSLATE_NOOP("Refusal", "%1 is read-only: the receiver reports "
                                                        "it but no command sets it"),
                           {std::string(def->key)});
        const SettingCommand *c = def->command;
        Refusal why = c->validate ? c->validate(*def, kv.value) : validateSetting(*def, kv.value);
        if (!why.empty()) return why;
        PlannedCommand &group = groupOf(out, c);
        for (const KeyValue &given : group.values)
            if (given.key == def->key)
                return refusal(QT_TRANSLATE_NOOP("Refusal", "%1 is given twice"),
                               {std::string(def->key)});
        group.values.push_back({std::string(def->key), kv.value});
    }
    sortByPlan(out);
    return {};
}

EncodeResult encodeSettings(const Dialect &d, std::span<const KeyValue> values) {
    EncodeResult result;
    std::vector<PlannedCommand> plan;
    if (Refusal why = planWrites(d, values, plan); !why.empty()) {
        result.refuse(std::move(why));
        return result;
    }
    // The confirming reads go after the writes that keep the link and before those that change it.
    std::vector<std::string> confirm;
    for (const PlannedCommand &p : plan) {
        if (!p.command->confirmedByRead || !p.command->read) continue;
        std::vector<PlannedCommand> readable{{p.command, {}}};
        for (const KeyValue &kv : p.values)
            if (findSetting(d.settings, kv.key)->access != SettingAccess::WriteOnly)
                readable.front().values.push_back(kv);
        if (!readable.front().values.empty())
            appendOnce(confirm, std::move(confirmingRead(readable.front()).sentences));
    }
    bool confirmed = false;
    for (const PlannedCommand &p : plan) {
        if (p.command->changesLink && !confirmed) {
            appendOnce(result.sentences, std::move(confirm));
            confirmed = true;
        }
        EncodeResult part = p.command->write(p.values);
        if (!part.ok()) {
            // The command's own refusal (its template when it gave one); nothing is sent.
            result.sentences.clear();
            result.refuse(part.refusal.text == part.error ? std::move(part.refusal)
                                                          : Refusal(std::move(part.error)));
            return result;
        }
        appendOnce(result.sentences, std::move(part.sentences));
    }
    if (!confirmed) appendOnce(result.sentences, std::move(confirm));
    return result;
}

EncodeResult encodeQueries(const Dialect &d, std::span<const std::string> keys) {
    EncodeResult result;
    std::vector<std::string> wanted(keys.begin(), keys.end());
    // "all": every setting the receiver reports.
    if (std::find(wanted.begin(), wanted.end(), "all") != wanted.end()) wanted = readableKeys(d);
    if (wanted.empty()) {
        result.refuse(Refusal("no setting given"));
        return result;
    }
    std::vector<PlannedCommand> plan;
    for (const std::string &k : wanted) {
        const SettingDef *def = findSetting(d.settings, k);
        if (!def) {
            result.refuse(unknownSetting(d, k));
            return result;
        }
        if (def->access == SettingAccess::WriteOnly || !def->command || !def->command->read) {
            result.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1 is write-only: the receiver "
                                                               "cannot report it"),
                                  {std::string(def->key)}));
            return result;
        }
        PlannedCommand &group = groupOf(plan, def->command);
        const bool dup = std::any_of(group.values.begin(), group.values.end(),
                                     [&](const KeyValue &kv) { return kv.key == def->key; });
        if (!dup) group.values.push_back({std::string(def->key), {}});
    }
    for (const PlannedCommand &p : plan) {
        std::vector<std::string> asked;
        for (const KeyValue &kv : p.values) asked.push_back(kv.key);
        EncodeResult part = p.command->read(asked);
        if (!part.ok()) return part;
        appendOnce(result.sentences, std::move(part.sentences));
    }
    return result;
}

std::vector<std::string> readableKeys(const Dialect &d) {
    std::vector<std::string> keys;
    for (const SettingDef &def : d.settings)
        if (def.access != SettingAccess::WriteOnly && def.command && def.command->read)
            keys.emplace_back(def.key);
    return keys;
}

namespace {

// "$GPSGG,GGA ON*6A" -> "GPSGG,GGA ON"
std::string bodyOf(std::string_view sentence) {
    if (!sentence.empty() && (sentence.front() == '$' || sentence.front() == '!'))
        sentence.remove_prefix(1);
    if (const auto star = sentence.rfind('*'); star != std::string_view::npos)
        sentence = sentence.substr(0, star);
    while (!sentence.empty() && (sentence.back() == '\r' || sentence.back() == '\n'))
        sentence.remove_suffix(1);
    return std::string(sentence);
}

// The values a row can take, when they are few enough to list.
std::vector<std::string> listedValues(const SettingDef &def) {
    std::vector<std::string> out;
    constexpr double kMaxRange = 64;
    switch (def.type) {
    case SettingType::Bool: out = {"1", "0"}; break;
    case SettingType::Enum:
        for (const auto &o : def.options) out.emplace_back(o.value);
        break;
    case SettingType::Integer:
        if (def.min && def.max && *def.max - *def.min <= kMaxRange)
            for (auto v = static_cast<long long>(*def.min); v <= static_cast<long long>(*def.max);
                 ++v)
                out.push_back(std::to_string(v));
        break;
    default: break;
    }
    return out;
}

} // namespace

std::vector<std::string> commandBodies(const Dialect &d) {
    std::vector<std::string> out;
    auto add = [&out](std::string_view sentence) {
        std::string body = bodyOf(sentence);
        if (!body.empty() && std::find(out.begin(), out.end(), body) == out.end())
            out.push_back(std::move(body));
    };
    if (!d.probeCommand.empty()) add(d.probeCommand);
    if (const std::vector<std::string> keys = readableKeys(d); !keys.empty())
        if (const EncodeResult q = encodeQueries(d, keys); q.ok())
            for (const std::string &s : q.sentences) add(s);
    for (const SettingDef &def : d.settings) {
        if (def.access == SettingAccess::ReadOnly || !def.command || !def.command->write) continue;
        for (const std::string &v : listedValues(def)) {
            const KeyValue kv{std::string(def.key), v};
            if (const EncodeResult w = encodeSettings(d, std::span(&kv, 1)); w.ok())
                for (const std::string &s : w.sentences) add(s);
        }
    }
    for (const ActionDef &a : d.actions) add(a.body);
    return out;
}

} // namespace gnss
