// The settings an engine knows, as label → value in the user's language.
#include "config/settings_snapshot.h"

#include "config/schema_texts.h"
#include "config/settings_engine.h"
#include "core/dialect.h"

namespace gnss::config {

std::vector<std::pair<QString, QString>> settingsSnapshot(const SettingsEngine &engine) {
    std::vector<std::pair<QString, QString>> out;
    const Dialect *d = engine.dialect();
    if (!d) return out;
    const SchemaTexts texts(d->id);
    for (const SettingDef &def : d->settings) {
        if (def.key.starts_with("action.")) continue;
        const ValueState st = engine.state(def.key);
        if (st != ValueState::Reported && st != ValueState::Written) continue;
        QString label = texts(def.label);
        if (!def.unit.empty()) label += QStringLiteral(" (%1)").arg(texts(def.unit));
        QString value = engine.displayValue(def.key);
        if (const auto raw = engine.receiverValue(def.key))
            for (const SettingOption &o : def.options)
                if (o.value == *raw) value = texts(o.label);
        out.emplace_back(label, value);
    }
    return out;
}

} // namespace gnss::config
