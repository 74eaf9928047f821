#pragma once
// The simulated ACME AX-1: standard NMEA 4.11 output with PACMS every epoch, its settings a
// SettingsStore of the schema, commands applied through the dialect's reading of them.
#include "sim/receiver.h"

namespace gnss::acme {

// The family's simulated receiver (its row in a sim::SimulatorTable).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);

} // namespace gnss::acme
