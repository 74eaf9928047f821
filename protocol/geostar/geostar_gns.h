#pragma once
// GeoS-5 subsidiary GNS sentences (the satellite count sits in the mode-indicator position); see
// geostar_gns.cpp. Everything else goes to the standard GNS decoder.
#include "core/dialect.h"

namespace gnss::geostar {

bool decodeGns(const Sentence &, DecodeContext &);

} // namespace gnss::geostar
