#include "gui/window_start.h"

#include "gui/main_window.h"
#include "gui/startup_options.h"

#include <QApplication>

namespace gnss::app {

QString startWindow(MainWindow &window, const StartupOptions &options) {
    if (!options.showDock.isEmpty() && !window.dockNames().contains(options.showDock))
        return QApplication::translate("StartupOptions", "Unknown dock '%1' (use %2)")
                .arg(options.showDock, window.dockNames().join(QStringLiteral(", ")));
    if (!options.open.isEmpty()) {
        window.openLog(options.open, options.at);
    } else {
        SourceSpec start;
        if (!options.port.isEmpty())
            start = {SourceSpec::Kind::Serial, options.port, options.baud};
        else if (!options.tcp.isEmpty())
            start = {SourceSpec::Kind::Tcp, options.tcp};
        else if (!options.replay.isEmpty())
            start = {SourceSpec::Kind::Replay, options.replay};
        else if (!options.sim.isEmpty())
            start = {SourceSpec::Kind::Simulator, options.sim};
        else if (!options.gpsd.isEmpty())
            start = {SourceSpec::Kind::Gpsd, options.gpsd};
        window.connectAtStart(start);
    }
    if (!options.showDock.isEmpty()) window.showDock(options.showDock);
    return {};
}

} // namespace gnss::app
