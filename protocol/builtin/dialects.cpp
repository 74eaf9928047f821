#include "builtin/dialects.h"

// One line per receiver family in builtinDialects() below (docs/adding-a-dialect.md).
#include "geostar/geostar_dialect.h"
#include "nemerix/nemerix_dialect.h"
#include "nmea/nmea_rules.h"
#include "nvs/nvs_dialect.h"

namespace gnss {

const Dialect &nmeaDialect() {
    static const Dialect d{
            .id = "nmea",
            .displayName = "NMEA-0183",
            .rules = standardSentenceRules(),
            // A standard query (NMEA 0183 "Q"): the computer (CC) asks the GPS (GP) for a GGA.
            .consoleExample = "$CCGPQ,GGA",
            // NMEA 0183 itself says 4800; receivers today (and the simulated one) start at 9600.
            .defaultBaud = 9600,
            .summary = "any NMEA-0183 receiver (2.x to 4.11): standard sentences only",
    };
    return d;
}

std::vector<const Dialect *> builtinDialects() {
    return {
            &nvs::dialect(),
            &geostar::dialect(),
            &nemerix::dialect(),
            &nmeaDialect(),
    };
}

DialectRegistry makeBuiltinRegistry() {
    return makeRegistry({});
}

DialectRegistry makeRegistry(const std::vector<const Dialect *> &more) {
    std::vector<const Dialect *> all = builtinDialects();
    // Another family before the plain NMEA record, which claims nothing but standard sentences.
    all.insert(all.end() - 1, more.begin(), more.end());
    return DialectRegistry(standardSentenceRules(), std::move(all));
}

} // namespace gnss
