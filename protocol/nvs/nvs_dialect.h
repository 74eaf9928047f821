#pragma once
// The NVS NV08C-RTK dialect record (picked up by protocol/dialects.cpp).
#include "core/dialect.h"

namespace gnss::nvs {

const gnss::Dialect &dialect();

// NVS meanings of GGA / PNVGTMC quality: 0 invalid, 1 autonomous, 2 differential, 4 RTK fixed,
// 5 float RTK, 6 estimated (dead reckoning).
FixType ggaQuality(int quality);

} // namespace gnss::nvs
