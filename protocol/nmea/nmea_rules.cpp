// The standard sentence table: one row per sentence type.
#include "nmea/nmea_rules.h"

#include "nmea/nmea_messages.h"

namespace gnss {

namespace {
using namespace nmea;
constexpr SentenceRule kStandardRules[] = {
        {"GGA", AddressMatch::Type, decodeGga, "Global positioning system fix data"},
        {"GLL", AddressMatch::Type, decodeGll, "Geographic position, latitude/longitude"},
        {"GNS", AddressMatch::Type, decodeGns, "GNSS fix data"},
        {"GSA", AddressMatch::Type, decodeGsa, "GNSS DOP and active satellites"},
        {"GSV", AddressMatch::Type, decodeGsv, "GNSS satellites in view"},
        {"RMC", AddressMatch::Type, decodeRmc, "Recommended minimum specific GNSS data"},
        {"VTG", AddressMatch::Type, decodeVtg, "Course over ground and ground speed"},
        {"ZDA", AddressMatch::Type, decodeZda, "Time and date"},
        {"HDT", AddressMatch::Type, decodeHdt, "Heading, true"},
        {"DTM", AddressMatch::Type, decodeDtm, "Datum reference"},
        {"GST", AddressMatch::Type, decodeGst, "GNSS pseudorange error statistics"},
        {"TXT", AddressMatch::Type, decodeTxt, "Text transmission"},
        {"Q", AddressMatch::Query, decodeQuery, "Query"},
};
} // namespace

std::span<const SentenceRule> standardSentenceRules() {
    return kStandardRules;
}

} // namespace gnss
