#pragma once
// The simulated ACME AX-1: standard NMEA 4.11 output with PACMS every epoch, its settings a
// SettingsStore of the schema, commands applied through the dialect's reading of them.
#include "core/dialect_hooks.h"

namespace gnss::acme {

MakeSimulatorHook makeSimulatedReceiver; // the record's simulator (Dialect::makeSimulator)

} // namespace gnss::acme
