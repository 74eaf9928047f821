#include "schema_catalog.h"

#include "core/dialect.h"
#include "core/dialect_registry.h"
#include "core/settings_plan.h"
#include "core/stream_decoder.h"
#include "sim/simulator_table.h"
#include "state/state_tracker.h"

#include <algorithm>
#include <regex>

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

std::vector<std::string> reportTexts(const Dialect &d, const DialectRegistry &registry,
                                     const sim::SimulatorTable &simulators) {
    std::vector<std::string> out;
    std::unique_ptr<sim::Receiver> rx = simulators.make(d.id);
    if (!rx) return out;
    // Everything the application asks: the identity, then every readable setting.
    std::string asked = std::string(d.probeCommand) + "\r\n";
    const std::vector<std::string> keys = readableKeys(d);
    if (!keys.empty())
        for (const std::string &q : encodeQueries(d, keys).sentences)
            asked += q.ends_with("\n") ? q : q + "\r\n";
    StreamDecoder decoder(registry);
    StateTracker tracker(&d);
    auto run = [&](double seconds) {
        for (double t = 0; t < seconds; t += 0.5) {
            rx->advance(0.5);
            decoder.feed(rx->takeOutput(), [&](const SentenceEvent &ev) {
                if (ev.message) tracker.add(ev.sentence, *ev.message, ev.dialect, [](auto &) {});
            });
        }
    };
    run(2);
    rx->receive(asked);
    run(10);
    auto add = [&](std::string s) {
        if (s.empty() || std::find(out.begin(), out.end(), s) != out.end()) return;
        out.push_back(std::move(s));
    };
    static const std::regex trailingNumber(R"( \d+$)");
    static const std::regex jsonKey(R"re("((?:[^"\\]|\\.)*)"\s*:)re");
    for (const auto &[title, json] : tracker.state().reports) {
        add(std::regex_replace(title, trailingNumber, ""));
        for (std::sregex_iterator it(json.begin(), json.end(), jsonKey), end; it != end; ++it)
            add((*it)[1].str());
    }
    return out;
}

std::string schemaCatalogSource(std::span<const Dialect *const> dialects,
                                const DialectRegistry &registry,
                                const sim::SimulatorTable &simulators) {
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
    // Report titles and field names: one context for every dialect (many fields are shared).
    std::vector<std::string> reports;
    for (const Dialect *d : dialects)
        for (std::string &t : reportTexts(*d, registry, simulators))
            if (std::find(reports.begin(), reports.end(), t) == reports.end())
                reports.push_back(std::move(t));
    if (!reports.empty()) {
        const std::string context = literal(kReportsContext);
        out += "\n// Receiver reports: titles and field names (the Receiver dock)\n";
        out += "static const char *const report_texts[] = {\n";
        for (const std::string &t : reports)
            out += "    QT_TRANSLATE_NOOP(" + context + ", " + literal(t) + "),\n";
        out += "};\n";
    }
    return out;
}

} // namespace gnss
