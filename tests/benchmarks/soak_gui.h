#pragma once
#include "soak_options.h"

namespace gnss::soak {
// The real main window offscreen, every dock shown, fed by SoakTransport: returns the exit code.
int runGuiSoak(const SoakOptions &o);
} // namespace gnss::soak
