#include "config/dialect_actions.h"

#include "core/sentence_builder.h"

namespace gnss::config {

std::string actionSentence(const ActionDef &a) {
    return buildSentence(a.body);
}

std::optional<Action> actionNamed(std::string_view name) {
    for (Action a : {Action::SaveToFlash, Action::RestoreDefaults, Action::ColdStart,
                     Action::WarmStart, Action::HotStart})
        if (toString(a) == name) return a;
    return std::nullopt;
}

} // namespace gnss::config
