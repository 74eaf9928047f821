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
        window.connectReceiversAtStart(options.sources);
    }
    if (!options.showDock.isEmpty()) window.showDock(options.showDock);
    return {};
}

} // namespace gnss::app
