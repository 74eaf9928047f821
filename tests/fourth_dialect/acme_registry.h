#pragma once
// The lines that register the test-only family beside the built-in ones: its dialect record in
// the registry, its simulated receiver in the simulators' table.
#include "acme_dialect.h"
#include "acme_sim_receiver.h"
#include "builtin/dialects.h"
#include "builtin/simulators.h"

namespace gnss::acme {

inline DialectRegistry registryWithAcme() {
    return makeRegistry({&dialect()});
}

inline sim::SimulatorTable simulatorsWithAcme() {
    return sim::makeSimulators({{"acme", makeSimulatedReceiver}});
}

} // namespace gnss::acme
