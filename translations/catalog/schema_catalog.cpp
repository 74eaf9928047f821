#include "schema_catalog.h"

#include "core/dialect.h"

#include <algorithm>

namespace gnss {
namespace {

// A C++ string literal of `s` (UTF-8 kept as is; lupdate reads sources as UTF-8).
std::string literal(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default: out += c;
        }
    }
    return out + '"';
}

// Prose, not a command template: what a translator has something to do with.
bool isProse(std::string_view s) {
    return !s.empty() && s.front() != '$' &&
           s.find_first_of("abcdefghijklmnopqrstuvwxyz") != std::string_view::npos;
}

} // namespace

std::vector<std::string> schemaTexts(const Dialect &d) {
    std::vector<std::string> out;
    auto add = [&](std::string_view s) {
        if (s.empty() || std::find(out.begin(), out.end(), s) != out.end()) return;
        out.emplace_back(s);
    };
    for (const SettingDef &def : d.settings) {
        add(def.group);
        add(def.label);
        add(def.unit);
        for (const SettingOption &o : def.options)
            if (o.label != o.value) add(o.label);
        add(def.help);
        // "Read back:" and "Written with:" show command templates, and prose where there is
        // no command ("none documented (...)").
        if (isProse(def.readBack)) add(def.readBack);
        if (isProse(def.write)) add(def.write);
    }
    for (const ActionDef &a : d.actions) {
        add(a.label);
        add(a.effect);
    }
    for (const Preset &p : d.presets) {
        add(p.name);
        add(p.description);
    }
    return out;
}

std::string schemaCatalogSource(std::span<const Dialect *const> dialects) {
    std::string out =
            "// Generated from the dialect records by the update_schema_catalog target (run by\n"
            "// update_translations): the texts of the settings schemas, actions and presets,\n"
            "// for lupdate. Read by lupdate only, never compiled. Do not edit: change the\n"
            "// dialect's record and regenerate.\n";
    for (const Dialect *d : dialects) {
        const std::vector<std::string> texts = schemaTexts(*d);
        if (texts.empty()) continue;
        const std::string context = literal("Schema/" + std::string(d->id));
        out += "\n// " + std::string(d->displayName) + "\n";
        out += "static const char *const " + std::string(d->id) + "_texts[] = {\n";
        for (const std::string &t : texts)
            out += "    QT_TRANSLATE_NOOP(" + context + ", " + literal(t) + "),\n";
        out += "};\n";
    }
    return out;
}

} // namespace gnss
