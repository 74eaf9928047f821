#include "gui/startup_options.h"

#include "link/gpsd_transport.h"
#include "logview/log_time.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>

namespace gnss::app {

using link::SourceSpec;

std::optional<StartupOptions> parseStartupOptions(const QStringList &arguments,
                                                  const QStringList &simulated, QString &error) {
    QCommandLineParser p;
    p.setApplicationDescription(
            QCoreApplication::translate("StartupOptions", "Configure and monitor GNSS receivers.") +
            QStringLiteral("\n\n") +
            QCoreApplication::translate("StartupOptions",
                                        "Exit status: 0 closed normally, 1 the log to open is "
                                        "not there or the --screenshot could not be saved, 2 "
                                        "usage error."));
    p.addHelpOption();
    p.addVersionOption();
    const QCommandLineOption port(
            {"p", "port"}, QCoreApplication::translate("StartupOptions", "Serial port."), "port");
    const QCommandLineOption baud(
            {"b", "baud"},
            QCoreApplication::translate("StartupOptions", "Baud rate (default: auto)."), "baud");
    const QCommandLineOption tcp(
            "tcp", QCoreApplication::translate("StartupOptions", "TCP source HOST:PORT."),
            "host:port");
    const QCommandLineOption replay(
            "replay", QCoreApplication::translate("StartupOptions", "Replay a recorded log."),
            "file");
    const QCommandLineOption openLog(
            "open",
            QCoreApplication::translate("StartupOptions",
                                        "Open a log in the offline viewer (a timeline, every dock "
                                        "at its cursor); the same as giving FILE alone."),
            "file");
    const QCommandLineOption at(
            "at",
            QCoreApplication::translate("StartupOptions",
                                        "With a log: start the viewer at this time of day "
                                        "(10:42:00), UTC time (2024-03-15T10:42:00Z) or epoch "
                                        "(#1200)."),
            "time");
    p.addPositionalArgument(
            "file", QCoreApplication::translate("StartupOptions", "A log to open in the viewer."),
            "[file]");
    const QCommandLineOption sim(
            "sim",
            QCoreApplication::translate("StartupOptions", "Built-in simulated receiver: %1.")
                    .arg(simulated.join(QStringLiteral(", "))),
            "dialect");
    const QCommandLineOption gpsd(
            "gpsd",
            QCoreApplication::translate("StartupOptions",
                                        "A receiver that gpsd holds: gpsd://HOST[:PORT][/DEVICE] "
                                        "(port 2947 and every device when left out)."),
            "url");
    const QCommandLineOption showDock(
            "show-dock",
            QCoreApplication::translate("StartupOptions",
                                        "Show this dock in front of its tab group: settings, "
                                        "console, sky, signal, fix, satellites, rtk, charts, "
                                        "corrections, deviation, attitude, stats, info, history, "
                                        "compare, qualify, base, serve; with "
                                        "a log open also logTrack, logSummary, logCharts, "
                                        "logEvents."),
            "name");
    const QCommandLineOption shot(
            "screenshot",
            QCoreApplication::translate("StartupOptions", "Save an image of the window and quit."),
            "file");
    const QCommandLineOption quit(
            "quit-after",
            QCoreApplication::translate("StartupOptions", "Quit after this many seconds."),
            "seconds");
    p.addOptions({port, baud, tcp, replay, openLog, at, sim, gpsd, showDock, shot, quit});
    if (!p.parse(arguments)) {
        error = p.errorText();
        return std::nullopt;
    }
    if (p.isSet("help")) p.showHelp(0);
    if (p.isSet("version")) {
        // As gnss-cli and gnss-sim print theirs: the program's name, then its version.
        std::printf("gnss-workbench %s\n", qPrintable(QCoreApplication::applicationVersion()));
        std::fflush(stdout);
        ::exit(0);
    }
    const QStringList files = p.positionalArguments();
    if (files.size() > 1 || (files.size() == 1 && p.isSet(openLog))) {
        error = QCoreApplication::translate("StartupOptions", "Unexpected argument '%1'")
                        .arg(files.constLast());
        return std::nullopt;
    }

    StartupOptions o;
    o.open = files.isEmpty() ? p.value(openLog) : files.constFirst();
    o.at = p.value(at);
    if (!o.at.isEmpty() && (o.open.isEmpty() || !logview::parseTimeSpec(o.at.toStdString()))) {
        error = o.open.isEmpty()
                        ? QCoreApplication::translate("StartupOptions", "--at needs a log to open")
                        : QCoreApplication::translate("StartupOptions",
                                                      "Invalid --at: %1 (write 10:42:00, "
                                                      "2024-03-15T10:42:00Z or #1200)")
                                  .arg(o.at);
        return std::nullopt;
    }
    o.port = p.values(port).value(0);
    o.tcp = p.values(tcp).value(0);
    o.replay = p.values(replay).value(0);
    o.sim = p.values(sim).value(0);
    o.gpsd = p.value(gpsd);
    o.showDock = p.value(showDock);
    o.screenshot = p.value(shot);
    // "auto", the default that --help names, may also be given.
    if (p.isSet(baud) && p.value(baud).compare(QLatin1String("auto"), Qt::CaseInsensitive) != 0) {
        bool ok = false;
        o.baud = p.value(baud).toInt(&ok);
        if (!ok || o.baud <= 0) {
            error = QCoreApplication::translate("StartupOptions", "Invalid baud rate: %1")
                            .arg(p.value(baud));
            return std::nullopt;
        }
    }
    if (p.isSet(quit)) {
        bool ok = false;
        o.quitAfter = p.value(quit).toDouble(&ok);
        if (!ok || o.quitAfter < 0) {
            error = QCoreApplication::translate("StartupOptions", "Invalid --quit-after: %1")
                            .arg(p.value(quit));
            return std::nullopt;
        }
    }
    // The live sources in the order given: the first is the one the docks show, and the
    // reference of the comparison.
    struct Kind {
        const QCommandLineOption *option;
        SourceSpec::Kind kind;
        int next = 0;
    };
    Kind kinds[] = {{&port, SourceSpec::Kind::Serial},
                    {&tcp, SourceSpec::Kind::Tcp},
                    {&gpsd, SourceSpec::Kind::Gpsd},
                    {&replay, SourceSpec::Kind::Replay},
                    {&sim, SourceSpec::Kind::Simulator}};
    for (const QString &arg : arguments.mid(1)) {
        if (arg == QLatin1String("--")) break;
        if (!arg.startsWith('-')) continue;
        const QString name =
                arg.mid(arg.startsWith(QLatin1String("--")) ? 2 : 1).section('=', 0, 0);
        for (Kind &k : kinds) {
            if (!k.option->names().contains(name)) continue;
            const QStringList values = p.values(*k.option);
            if (k.next < values.size())
                o.sources << SourceSpec{k.kind, values[k.next++],
                                        k.kind == SourceSpec::Kind::Serial ? o.baud : 0};
        }
    }
    for (SourceSpec &spec : o.sources) {
        if (spec.kind == SourceSpec::Kind::Simulator && !simulated.contains(spec.name)) {
            error = QCoreApplication::translate("StartupOptions",
                                                "Unknown simulated receiver '%1' (use %2)")
                            .arg(spec.name, simulated.join(", "));
            return std::nullopt;
        }
        if (spec.kind == SourceSpec::Kind::Gpsd) {
            link::GpsdTransport::Target target;
            QString why;
            if (!link::GpsdTransport::parseTarget(spec.name, target, &why)) {
                error = QCoreApplication::translate("StartupOptions", "Invalid --gpsd: %1")
                                .arg(why);
                return std::nullopt;
            }
            // The source's name is what follows the scheme (SourceSpec adds it back).
            spec.name = spec.name.trimmed();
            if (spec.name.startsWith(QLatin1String("gpsd://"), Qt::CaseInsensitive))
                spec.name = spec.name.mid(7);
        }
    }
    o.gpsd.clear();
    for (const SourceSpec &spec : std::as_const(o.sources))
        if (spec.kind == SourceSpec::Kind::Gpsd && o.gpsd.isEmpty()) o.gpsd = spec.name;
    if (!o.open.isEmpty() && !o.sources.isEmpty()) {
        error = QCoreApplication::translate("StartupOptions",
                                            "Give live sources (--port, --tcp, --gpsd, --replay, "
                                            "--sim) or a log to open, not both.");
        return std::nullopt;
    }
    return o;
}

QString missingLog(const StartupOptions &o) {
    if (o.open.isEmpty() || QFileInfo(o.open).isFile()) return {};
    return QCoreApplication::translate("StartupOptions", "No such log: %1").arg(o.open);
}

bool asksForHelpOrVersion(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--") break;
        if (a == "--help" || a == "-h" || a == "--help-all" || a == "--version" || a == "-v")
            return true;
    }
    return false;
}

} // namespace gnss::app
