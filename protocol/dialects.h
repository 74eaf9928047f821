#pragma once
// The built-in dialects. A new receiver family adds its record to the list in dialects.cpp.
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
