// gnss-cli config: a receiver's settings from the command line, on the settings engine
// (protocol/config) that the settings dock uses.
//
//   gnss-cli config (--port P [--baud B] | --tcp H:P | --sim DIALECT) [--dialect D] get [KEY...]
//   ... set KEY=VALUE...     apply; one JSON line per command, then the verification
//   ... export FILE          read everything, write a versioned JSON profile
//   ... apply FILE           apply the profile's difference; non-zero if anything was refused
//                            or did not verify
//   ... diff FILE            one JSON line per difference; exit 1 when there are any
//   ... action save|defaults|cold|warm|hot   the receiver-wide actions the dialect offers
//
// Without --baud the speed is detected; without --dialect the receiver is identified.
// Before any Qt header: core headers have members named emit, which Qt defines as a macro.
#include "core/json_writer.h"
#include "core/settings_plan.h"
#include "core/stream_decoder.h"

#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/settings_link.h"
#include "config/refusal_text.h"
#include "config/settings_engine.h"
#include "link/command_queue.h"
#include "link/sentence_stream.h"
#include "link/vendor_detector.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace gnss::cli {
namespace {

using config::OperationReport;
using config::SettingsEngine;

void say(const QString &s) {
    std::fprintf(stderr, "gnss-cli: %s\n", s.toUtf8().constData());
}

// The schema keys of `typed` ("PVTRATE", "rtk.elgps": the forms findSetting takes), or false
// with the unknown or ambiguous one said (and the keys it could mean).
bool schemaKeys(const Dialect &d, std::vector<std::string> &keys) {
    for (auto &k : keys) {
        const SettingDef *def = findSetting(d.settings, k);
        if (!def) {
            say(config::refusalText(unknownSetting(d, k), d.id));
            return false;
        }
        k = std::string(def->key);
    }
    return true;
}

int get(SettingsEngine &engine, std::vector<std::string> keys) {
    if (!schemaKeys(*engine.dialect(), keys)) return 2;
    const auto r = runOperation(engine, [&] { return engine.read(keys); });
    const bool ok = reportRead(r);
    std::string out;
    JsonWriter w(out);
    w.beginObject().field("dialect", engine.dialect()->id);
    const auto &id = engine.identity();
    w.field("model", textOrNull(id.model));
    w.field("firmware", textOrNull(id.firmware));
    w.key("values").beginObject();
    std::vector<std::string> writeOnly;
    for (const auto &def : engine.dialect()->settings) {
        if (def.key.starts_with("action.")) continue;
        bool wanted = keys.empty();
        for (const auto &k : keys) wanted = wanted || k == def.key;
        if (!wanted) continue;
        w.field(def.key, engine.receiverValue(def.key));
        if (engine.state(def.key) == config::ValueState::WriteOnly) writeOnly.emplace_back(def.key);
    }
    w.endObject();
    w.key("write_only").beginArray();
    for (const auto &k : writeOnly) w.value(k);
    w.endArray().endObject();
    printLine(out);
    return ok ? 0 : 1;
}

} // namespace

int cmdConfig(const CliContext &ctx) {
    const Args &args = ctx.args;
    const auto &pos = args.positionals();
    if (pos.empty()) {
        say(QObject::tr("config needs an action: get, set, export, apply, diff or action"));
        return 2;
    }
    const std::string action = pos.front();
    const std::vector<std::string> rest(pos.begin() + 1, pos.end());
    std::vector<KeyValue> sets;
    if (action == "set") {
        for (const auto &a : rest) {
            const auto eq = a.find('=');
            if (eq == std::string::npos || eq == 0) {
                say(QObject::tr("set expects KEY=VALUE, got '%1'").arg(QString::fromStdString(a)));
                return 2;
            }
            sets.push_back({a.substr(0, eq), a.substr(eq + 1)});
        }
        if (sets.empty()) {
            say(QObject::tr("set needs at least one KEY=VALUE"));
            return 2;
        }
    } else if (action == "export" || action == "apply" || action == "diff") {
        if (rest.size() != 1) {
            say(QObject::tr("config %1 needs one FILE").arg(QString::fromStdString(action)));
            return 2;
        }
    } else if (action == "action") {
        if (rest.size() != 1) {
            say(QObject::tr("config action needs one of save, defaults, cold, warm, hot"));
            return 2;
        }
    } else if (action != "get") {
        say(QObject::tr("unknown config action '%1': get, set, export, apply, diff or action")
                    .arg(QString::fromStdString(action)));
        return 2;
    }

    int qargc = 1;
    char name[] = "gnss-cli";
    char *qargv[] = {name, nullptr};
    QCoreApplication app(qargc, qargv);
    Link l = openLink(ctx, args);
    if (!l.connection) return l.usageError ? 2 : 1;
    l.connection->commands()->setDialect(l.dialect);
    SettingsEngine engine;
    engine.attach(l.connection.get(), l.dialect);

    if (action == "get") return get(engine, rest);
    if (action == "set") {
        // Each by its schema key, however it was typed; an unknown one refused before sending.
        std::vector<std::string> keys;
        for (const auto &kv : sets) keys.push_back(kv.key);
        if (!schemaKeys(*l.dialect, keys)) return 2;
        for (std::size_t i = 0; i < sets.size(); ++i) sets[i].key = keys[i];
        // Only what differs is sent: the engine reads the receiver first.
        if (!keys.empty()) runOperation(engine, [&] { return engine.read(keys); });
        return applyValues(engine, [&] { return engine.apply(sets); });
    }
    if (action == "action") {
        if (const auto a = config::actionNamed(rest.front()))
            return applyValues(engine, [&] { return engine.runAction(*a); });
        say(QObject::tr("unknown action '%1': save, defaults, cold, warm or hot")
                    .arg(QString::fromStdString(rest.front())));
        return 2;
    }
    const QString path = QString::fromStdString(rest.front());
    if (action == "export") {
        if (!reportRead(runOperation(engine, [&] { return engine.read(); }))) return 1;
        QString error;
        const config::Profile p = engine.exportProfile();
        if (!config::saveProfile(path, p, &error)) {
            say(error);
            return 1;
        }
        say(QObject::tr("%n setting(s) of the %1 receiver written to %2", nullptr,
                        static_cast<int>(p.values.size()))
                    .arg(QString::fromStdString(p.dialect), path));
        return 0;
    }
    // A file that cannot be read is a failure (1); one that is not a profile for this receiver
    // is a wrong request (2).
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        say(QObject::tr("cannot read %1: %2").arg(path, file.errorString()));
        return 1;
    }
    config::Profile profile;
    QString error;
    if (!config::profileFromJson(file.readAll(), profile, &error, l.dialect)) {
        say(error);
        return 2;
    }
    // The profile's form, dialect and keys were checked when it was read, before the port was
    // written to. The receiver's model is known once it is read: nothing is written to a
    // receiver of another model; and the values that differ are all checked before the first
    // is sent (the engine's apply).
    if (!reportRead(runOperation(engine, [&] { return engine.read(); }))) return 1;
    if (action == "apply") {
        if (const QString why =
                    config::profileMismatch(profile, l.dialect, engine.identity().model);
            !why.isEmpty()) {
            say(why);
            return 2;
        }
        return applyValues(engine, [&] { return engine.applyProfile(profile); });
    }
    // diff
    const auto entries = engine.diff(profile);
    for (const auto &d : entries) {
        printJson([&](JsonWriter &w) {
            w.beginObject()
                    .field("key", d.key)
                    .field("profile", d.profileValue)
                    .field("receiver", d.receiverKnown ? std::optional<std::string>(d.receiverValue)
                                                       : std::nullopt)
                    .endObject();
        });
    }
    if (entries.empty()) return 0;
    say(QObject::tr("%n setting(s) of the receiver differ from %1", nullptr,
                    static_cast<int>(entries.size()))
                .arg(path));
    return 1;
}

} // namespace gnss::cli
