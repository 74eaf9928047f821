#pragma once
// The real MainWindow as a user first starts it, for the window tests: the built-in dialects,
// the application's transports, its settings in a file of its own (none saved yet), shown on the
// 1280x800 offscreen screen (tests/acceptance/CMakeLists.txt).
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/main_window.h"

#include <QSettings>
#include <QTemporaryDir>

namespace gnss::test {

struct LaptopWindow {
    QTemporaryDir dir;
    DialectRegistry registry = makeBuiltinRegistry();
    link::TransportFactory transports = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QSettings settings{settingsFile(), QSettings::IniFormat};
    app::MainWindow w{registry, transports, &settings};

    LaptopWindow() { w.show(); }
    QString settingsFile() const { return dir.filePath("settings.ini"); }
};

} // namespace gnss::test
