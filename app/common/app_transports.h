#pragma once
// The sources the applications know: the link library's (serial, TCP, replay) and the built-in
// simulated receivers. One factory for the GUI and every gnss-cli command.
#include "transport_factory.h"

#include "core/dialect_registry.h"

#include <QStringList>

namespace gnss::app {

// The registry's records make the simulated receivers; it outlives the factory.
link::TransportFactory makeTransportFactory(const DialectRegistry &registry);

// The dialects of `registry` the simulator can play (for source lists and option checks).
QStringList simulatedDialects(const DialectRegistry &registry);

} // namespace gnss::app
