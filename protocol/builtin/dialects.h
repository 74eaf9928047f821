#pragma once
// The built-in dialects: the composition root of the receiver families, the one place that
// lists them. A new family adds its record to builtinDialects() in dialects.cpp (and, when it
// has a simulated receiver, its row to simulators.cpp).
#include "core/dialect_registry.h"

namespace gnss {

// The plain NMEA-0183 dialect (standard sentences only).
const Dialect &nmeaDialect();

// The built-in dialect records, in lookup order.
std::vector<const Dialect *> builtinDialects();

// A registry of every built-in dialect; the application builds one and injects it.
DialectRegistry makeBuiltinRegistry();
// The built-in dialects and `more` (a family registered by a program or a test: one line).
DialectRegistry makeRegistry(const std::vector<const Dialect *> &more);

} // namespace gnss
