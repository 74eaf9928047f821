#include "dialects.h"

// One line per receiver family (DESIGN.md: "a new vendor costs one folder plus one registry line").
#include "geostar/geostar_dialect.h"
#include "nemerix/nemerix_dialect.h"
#include "nvs/nvs_dialect.h"

namespace gnss {

const Dialect &nmeaDialect() {
    static const Dialect d{
            .id = "nmea",
            .displayName = "NMEA-0183",
            .rules = standardSentenceRules(),
            // A standard query (NMEA 0183 "Q"): the computer (CC) asks the GPS (GP) for a GGA.
            .consoleExample = "$CCGPQ,GGA",
    };
    return d;
}

DialectRegistry makeBuiltinRegistry() {
    return DialectRegistry({
            &nvs::dialect(),
            &geostar::dialect(),
            &nemerix::dialect(),
            &nmeaDialect(),
    });
}

} // namespace gnss
