#pragma once
// The built-in simulated receivers: one row per family that has one, in the order of
// builtinDialects() (dialects.h). gnss-sim, the applications' built-in source and the tests make
// their receivers from this table; a program or a test adds a family of its own with
// makeSimulators({{"acme", acme::makeSimulatedReceiver}}).
#include "sim/simulator_table.h"

namespace gnss::sim {

// The built-in families' table (constant data, like the dialect records).
const SimulatorTable &builtinSimulators();
// The built-in families and `more`, each of `more` before the plain NMEA receiver (as
// makeRegistry places a family before the plain NMEA record).
SimulatorTable makeSimulators(const std::vector<SimulatedFamily> &more);
// builtinSimulators().make(dialect, options).
std::unique_ptr<Receiver> makeReceiver(std::string_view dialect, const SimOptions &options = {});

} // namespace gnss::sim
