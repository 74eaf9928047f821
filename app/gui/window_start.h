#pragma once
// What gnss-workbench's start-up options do to its window, in the order a person would expect:
// the log opened or the source connected first, then the dock asked for with --show-dock brought
// forward (opening a log brings the log's own docks forward, which would hide it otherwise).
#include <QString>

namespace gnss::app {

class MainWindow;
struct StartupOptions;

// Returns an error (translated) and does nothing when the --show-dock name is not a dock's.
QString startWindow(MainWindow &window, const StartupOptions &options);

} // namespace gnss::app
