#pragma once
// Nemerix VT002 (NMEA 3.0 + $PNMRX extensions). Picked up by protocol/dialects.cpp.
#include "core/dialect.h"

namespace gnss::nemerix {

const gnss::Dialect &dialect();

} // namespace gnss::nemerix
