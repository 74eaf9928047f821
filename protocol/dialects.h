#pragma once
// The built-in dialects. A new receiver family adds its record to the list in dialects.cpp.
#include "core/dialect_registry.h"

namespace gnss {

// The plain NMEA-0183 dialect (standard sentences only).
const Dialect &nmeaDialect();

// A registry of every built-in dialect; the application builds one and injects it.
DialectRegistry makeBuiltinRegistry();

} // namespace gnss
