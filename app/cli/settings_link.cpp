// The link and the settings engine behind the commands that change a receiver's settings
// (gnss-cli config, gnss-cli base).
#include "core/json_writer.h"

#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/settings_link.h"
#include "link/vendor_detector.h"

#include <QEventLoop>
#include <QTimer>

#include <cstdio>

namespace gnss::cli {

using config::OperationReport;
using config::SettingsEngine;

namespace {
void say(const QString &s) {
    std::fprintf(stderr, "gnss-cli: %s\n", s.toUtf8().constData());
}
} // namespace

// Runs an engine operation to its end.
OperationReport runOperation(SettingsEngine &engine, const std::function<bool()> &start) {
    QEventLoop loop;
    bool done = false;
    auto c = QObject::connect(&engine, &SettingsEngine::finished, &loop, [&] {
        done = true;
        loop.quit();
    });
    start();
    if (!done) loop.exec();
    QObject::disconnect(c);
    return engine.lastReport();
}

// The verification of an apply, one line per setting, then the summary.
void printChecks(const OperationReport &r) {
    for (const auto &c : r.checks) {
        printJson([&](JsonWriter &w) {
            w.beginObject()
                    .field("key", c.key)
                    .field("set", c.wanted)
                    .field("reported", textOrNull(c.reported))
                    .field("verdict", utf8(config::verdictName(c.verdict)))
                    .endObject();
        });
    }
    printJson([&](JsonWriter &w) {
        w.beginObject()
                .field("ok", r.ok())
                .field("nothing_to_do", r.nothingToDo)
                .field("commands", static_cast<int>(r.commands.size()))
                .field("failed_commands", r.failedCommands())
                .field("failed_checks", r.failedChecks());
        w.key("companions").beginArray();
        for (const auto &kv : r.companions) w.value(kv.key + "=" + kv.value);
        w.endArray();
        w.field("error", textOrNull(r.error)).endObject();
    });
}

bool reportRead(const OperationReport &r) {
    if (r.ok()) return true;
    say(QObject::tr("reading the settings failed: %1")
                .arg(r.error.isEmpty()
                             ? QObject::tr("%n command(s) failed", nullptr, r.failedCommands())
                             : r.error));
    for (const auto &c : r.commands)
        if (c.outcome != link::CommandOutcome::Accepted && c.outcome != link::CommandOutcome::Sent)
            say(QString("  %1: %2").arg(c.sentence, c.detail));
    return false;
}

// Opens the source (any the application knows), finds the speed and the dialect; an empty Link
// after saying why.
Link openLink(const CliContext &ctx, const Args &args) {
    Link l;
    std::string error;
    const auto spec = sourceFromArgs(args,
                                     {link::SourceSpec::Kind::Serial, link::SourceSpec::Kind::Tcp,
                                      link::SourceSpec::Kind::Simulator},
                                     error);
    if (!spec) {
        say(QString::fromStdString(error));
        l.usageError = true;
        return l;
    }
    const std::string dialectId = args.option("dialect").value_or(
            spec->kind == link::SourceSpec::Kind::Simulator ? spec->name.toStdString() : "auto");
    if (dialectId != "auto") {
        l.dialect = ctx.registry.find(dialectId);
        if (!l.dialect) {
            say(QObject::tr("unknown dialect '%1'").arg(QString::fromStdString(dialectId)));
            l.usageError = true;
            return l;
        }
    }
    OpenOptions o;
    o.autoReconnect = false;
    QString why;
    l.connection = openConnection(ctx, *spec, o, why);
    if (!l.connection) {
        say(why);
        return {};
    }
    if (!l.dialect) {
        link::VendorDetector vendor(l.connection->stream());
        QEventLoop loop;
        link::VendorIdentity id;
        QObject::connect(&vendor, &link::VendorDetector::finished,
                         [&](const link::VendorIdentity &v) {
                             id = v;
                             loop.quit();
                         });
        QTimer::singleShot(0, &vendor, &link::VendorDetector::start);
        loop.exec();
        if (!id.found) {
            say(QObject::tr("the receiver's dialect was not recognised (%1); give --dialect")
                        .arg(id.error));
            return {};
        }
        l.dialect = ctx.registry.find(id.dialect.toStdString());
    }
    if (l.dialect && l.dialect->settings.empty()) {
        say(QObject::tr("the %1 dialect has no settings")
                    .arg(QString::fromUtf8(l.dialect->id.data(),
                                           static_cast<qsizetype>(l.dialect->id.size()))));
        return {};
    }
    l.connection->stream()->setDialect(l.dialect);
    return l;
}

int applyValues(SettingsEngine &engine, const std::function<bool()> &start) {
    auto c = QObject::connect(&engine, &SettingsEngine::commandFinished,
                              [](const link::CommandResult &r) { printCommandResult(r, false); });
    const auto r = runOperation(engine, start);
    QObject::disconnect(c);
    printChecks(r);
    if (!r.error.isEmpty()) say(r.error);
    if (r.ok()) return 0;
    // A value out of range, a read-only setting: the request was wrong, and nothing was sent.
    return r.refusedBeforeSending() ? 2 : 1;
}

} // namespace gnss::cli
