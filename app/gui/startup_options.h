#pragma once
// Command-line options of gnss-workbench.
#include "link/source_spec.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <optional>

namespace gnss::app {

struct StartupOptions {
    QString port;         // --port P
    int baud = 0;         // --baud B (0: auto)
    QString tcp;          // --tcp HOST:PORT
    QString replay;       // --replay FILE
    QString open;         // FILE or --open FILE: a log in the offline viewer
    QString at;           // --at TIME: where the viewer's cursor starts (10:42:00, #1200)
    QString sim;          // --sim nvs|geostar|nemerix|nmea
    QString gpsd;         // --gpsd HOST[:PORT][/DEVICE] (or gpsd://...)
    QString showDock;     // --show-dock NAME: show and raise this dock (settings, console, ...)
    QString screenshot;   // --screenshot FILE: save an image of the window, then quit
    double quitAfter = 0; // --quit-after SECONDS
    // Every live source, in the order given (each of --port, --tcp, --gpsd, --replay and --sim
    // may be repeated: one receiver each; --baud is every port's). The single fields above hold
    // the first of each kind.
    QList<link::SourceSpec> sources;
};

// Parses the arguments; on error returns nullopt with `error` set (already translated).
// `simulated`: the dialects the built-in simulator plays (what --sim accepts). --help and
// --version print to standard output and exit(0). The --show-dock name is checked by the window,
// which knows its docks.
std::optional<StartupOptions> parseStartupOptions(const QStringList &arguments,
                                                  const QStringList &simulated, QString &error);

// Why the log to open cannot be (it is not a file), empty when it can: a failure (exit 1), where
// a malformed command line is a usage error (2).
QString missingLog(const StartupOptions &o);

// Whether the command line asks only to print something (--help, -h, --help-all, --version,
// -v), looked at before the application object exists.
bool asksForHelpOrVersion(int argc, char **argv);

} // namespace gnss::app
