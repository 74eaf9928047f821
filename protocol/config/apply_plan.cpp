#include "config/apply_plan.h"

#include "config/setting_values.h"
#include "core/sentence.h"
#include "core/setting_command.h"
#include "link/command_queue.h"

#include <QString>

#include <algorithm>

namespace gnss::config {

std::vector<KeyValue> withCompanions(const Dialect &d, std::vector<KeyValue> changes,
                                     const ValueInForce &inForce,
                                     std::vector<KeyValue> *companions) {
    auto has = [&](std::string_view key) {
        return std::any_of(changes.begin(), changes.end(),
                           [&](const KeyValue &kv) { return kv.key == key; });
    };
    auto add = [&](const SettingDef &def) {
        if (has(def.key) || !isWritable(def)) return;
        std::string v;
        if (auto rv = inForce ? inForce(def.key) : std::nullopt)
            v = *rv;
        else if (!def.defaultValue.empty())
            v = std::string(def.defaultValue);
        else
            return;
        changes.push_back({std::string(def.key), v});
        if (companions) companions->push_back(changes.back());
    };
    const std::vector<KeyValue> original = changes;
    // The settings of one command go together: the schema rows name their command, and the
    // others' values in force complete the change.
    for (const auto &kv : original) {
        const SettingDef *def = findSetting(d.settings, kv.key);
        if (!def || !def->command || !def->command->together) continue;
        for (const auto &other : d.settings)
            if (other.command == def->command) add(other);
    }
    return changes;
}

namespace {
const ReplyRule *ruleOf(const Dialect &d, const std::string &sentence) {
    Sentence s;
    return s.parse(sentence) ? link::CommandQueue::findRule(d.replyRules, s) : nullptr;
}

bool setsHostPort(const Dialect &d, const std::string &sentence) {
    const std::string_view host = d.linkSpeed.commandPrefix;
    return !host.empty() && sentence.size() > 1 &&
           std::string_view(sentence).substr(1).starts_with(host);
}
} // namespace

int effectRank(const Dialect &d, const std::string &sentence) {
    const ReplyRule *rule = ruleOf(d, sentence);
    if (!rule) return 0;
    switch (rule->effect) {
    case CommandEffect::None:
    case CommandEffect::ChangesOutput: return 0;
    case CommandEffect::ResetsReceiver: return 1;
    case CommandEffect::ChangesBaud: return setsHostPort(d, sentence) ? 3 : 2;
    case CommandEffect::ChangesProtocol: return 4;
    }
    return 0;
}

void orderForSending(const Dialect &d, std::vector<std::string> &sentences) {
    // Each sentence parsed and ranked once, not at every comparison.
    std::vector<std::pair<int, std::string>> ranked;
    ranked.reserve(sentences.size());
    for (std::string &s : sentences) ranked.emplace_back(effectRank(d, s), std::move(s));
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    for (std::size_t i = 0; i < ranked.size(); ++i) sentences[i] = std::move(ranked[i].second);
}

std::optional<int> lineBaudAfter(const Dialect &d, const std::string &sentence, int lineBaud,
                                 const std::vector<KeyValue> &applying) {
    if (lineBaud <= 0) return std::nullopt;
    const ReplyRule *rule = ruleOf(d, sentence);
    if (!rule || rule->effect != CommandEffect::ChangesBaud) return std::nullopt;
    // Another port's speed: the host's side of the line stays where it is.
    if (!setsHostPort(d, sentence)) return lineBaud;
    // The host's port: the link follows to the speed set ("BDR057" does not spell it out).
    std::optional<int> to;
    if (const SettingDef *speed = findSettingByRole(d.settings, SettingRole::PortSpeed))
        for (const auto &kv : applying)
            if (kv.key == speed->key) to = QString::fromStdString(kv.value).toInt();
    return to;
}

} // namespace gnss::config
