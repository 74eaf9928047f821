#pragma once
// The GeoStar GeoS-5 dialect record (spec: geostar-geos5-nmea-v4.0.ru.txt, docs/spec-notes.md).
#include "core/dialect.h"

namespace gnss::geostar {

const gnss::Dialect &dialect();

} // namespace gnss::geostar
