#pragma once
// Command-line options of gnss-workbench.
#include <QString>
#include <QStringList>
#include <optional>

namespace gnss::app {

struct StartupOptions {
    QString port;         // --port P
    int baud = 0;         // --baud B (0: auto)
    QString tcp;          // --tcp HOST:PORT
    QString replay;       // --replay FILE
    QString sim;          // --sim nvs|geostar|nemerix|nmea
    QString screenshot;   // --screenshot FILE: save an image of the window, then quit
    double quitAfter = 0; // --quit-after SECONDS
};

// Parses the arguments; on error returns nullopt with `error` set (already translated).
// `simulated`: the dialects the built-in simulator plays (what --sim accepts).
std::optional<StartupOptions> parseStartupOptions(const QStringList &arguments,
                                                  const QStringList &simulated, QString &error);

} // namespace gnss::app
