#pragma once
// The sources the applications know: the link library's (serial, TCP, gpsd, replay) and the
// simulated receivers of a table (the built-in one: protocol/builtin/simulators.h). One factory
// for the GUI and every gnss-cli command.
#include "link/transport_factory.h"

#include "sim/simulator_table.h"

#include <QStringList>

namespace gnss::app {

// `simulators` makes the simulated receivers (--sim NAME) and outlives the factory; the factory
// names them (names(Kind::Simulator)) in the table's order.
link::TransportFactory makeTransportFactory(const sim::SimulatorTable &simulators);

// The dialects the simulator can play (for source lists and option checks).
QStringList simulatedDialects(const sim::SimulatorTable &simulators);

} // namespace gnss::app
