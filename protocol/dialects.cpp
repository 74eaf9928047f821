#include "dialects.h"

// One line per receiver family (DESIGN.md: "a new vendor costs one folder plus one registry line").
// Each vendor folder declares its record in <vendor>/<vendor>_dialect.h.
#if __has_include("nvs/nvs_dialect.h")
#include "nvs/nvs_dialect.h"
#define GNSS_HAVE_NVS 1
#endif
#if __has_include("geostar/geostar_dialect.h")
#include "geostar/geostar_dialect.h"
#define GNSS_HAVE_GEOSTAR 1
#endif
#if __has_include("nemerix/nemerix_dialect.h")
#include "nemerix/nemerix_dialect.h"
#define GNSS_HAVE_NEMERIX 1
#endif

namespace gnss {

const Dialect &nmeaDialect() {
    static const Dialect d{
            .id = "nmea",
            .displayName = "NMEA-0183",
            .rules = standardSentenceRules(),
    };
    return d;
}

DialectRegistry makeBuiltinRegistry() {
    return DialectRegistry({
#ifdef GNSS_HAVE_NVS
            &nvs::dialect(),
#endif
#ifdef GNSS_HAVE_GEOSTAR
            &geostar::dialect(),
#endif
#ifdef GNSS_HAVE_NEMERIX
            &nemerix::dialect(),
#endif
            &nmeaDialect(),
    });
}

} // namespace gnss
