#pragma once
// The sources the applications know: the link library's (serial, TCP, replay) and the built-in
// simulated receivers. One factory for the GUI and every gnss-cli command.
#include "transport_factory.h"

#include <QStringList>

namespace gnss::app {

link::TransportFactory makeTransportFactory();

// The dialects the simulator can play (for source lists and option checks).
QStringList simulatedDialects();

} // namespace gnss::app
