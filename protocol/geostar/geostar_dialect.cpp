// GeoStar GeoS-5: sentence table and the dialect record.
#include "geostar_dialect.h"
#include "geostar_actions.h"
#include "geostar_state.h"

#include "geostar_gns.h"
#include "geostar_messages.h"
#include "geostar_numbering.h"
#include "geostar_reply_rules.h"
#include "geostar_schema.h"

namespace gnss::geostar {
namespace {

constexpr SentenceRule kRules[] = {
        {"GPSGG", AddressMatch::Whole, decodeSgg,
         "GeoS-5 proprietary: RQUERY/NQUERY replies, JAMDET and every input command"},
        {"RLM", AddressMatch::Type, decodeRlm, "Galileo return link message"},
        // Subsidiary per-system GNS (satellite count in the mode position), else standard GNS.
        {"GNS", AddressMatch::Type, decodeGns, "GNSS fix data (with GeoS-5 subsidiary sentences)"},
};

constexpr std::string_view kCommandNames[] = {
        "GPSGG,RQUERY", "GPSGG,NQUERY", "GPSGG,CSTART", "GPSGG,WSTART", "GPSGG,HSTART",
        "GPSGG,SAVEFL", "GPSGG,SWPROT", "GPSGG,BDR004", "GPSGG,BDR009", "GPSGG,BDR019",
        "GPSGG,BDR038", "GPSGG,BDR057", "GPSGG,BDR115", "GPSGG,BDR230", "GPSGG,BDR460",
        "GPSGG,BDR921", "GPSGG,STOP01", "GPSGG,STOP02", "GPSGG,GGA ON", "GPSGG,GGAOFF",
        "GPSGG,GLL ON", "GPSGG,GLLOFF", "GPSGG,GSA ON", "GPSGG,GSAOFF", "GPSGG,GSV ON",
        "GPSGG,GSVOFF", "GPSGG,RMC ON", "GPSGG,RMCOFF", "GPSGG,VTG ON", "GPSGG,VTGOFF",
        "GPSGG,ZDA ON", "GPSGG,ZDAOFF", "GPSGG,DTM ON", "GPSGG,DTMOFF", "GPSGG,RLM ON",
        "GPSGG,RLMOFF", "GPSGG,NMEAV2", "GPSGG,NMEAV4", "GPSGG,RATE01", "GPSGG,RATE02",
        "GPSGG,RATE05", "GPSGG,RATE10", "GPSGG,PSM ON", "GPSGG,PSMOFF", "GPSGG,ELEV05",
        "GPSGG,ELEV06", "GPSGG,ELEV07", "GPSGG,ELEV08", "GPSGG,ELEV09", "GPSGG,ELEV10",
        "GPSGG,ELEV11", "GPSGG,ELEV12", "GPSGG,ELEV13", "GPSGG,ELEV14", "GPSGG,ELEV15",
        "GPSGG,DATP90", "GPSGG,DATW84", "GPSGG,NVSGPS", "GPSGG,NVSGLN", "GPSGG,NVSMIX",
};

} // namespace

const Dialect &dialect() {
    static const Dialect d{
            .id = "geostar",
            .displayName = "GeoStar GeoS-5",
            .rules = kRules,
            .checksumOptional = false, // "the checksum is sent in every message" (section 2)
            .ggaQuality = ggaQuality,
            .modeIndicator = modeIndicator,
            .fixNote = fixNote,
            .mapSatellite = mapSatellite,
            .updateState = updateState,
            .settings = settingsSchema(),
            .replyRules = replyRules(),
            .extractSettings = extractSettings,
            .probeCommand = "$GPSGG,RQUERY*70",
            .commandNames = kCommandNames,
            .consoleExample = "$GPSGG,RQUERY",
            .defaultBaud = kDefaultBaud,
            .supportedBauds = kSupportedBauds,
            .actions = kActions,
            .presets = kPresets,
            .linkSpeed = {"GPSGG,BDR"},
            .summary = "GeoStar GeoS-5 ($GPSGG,...): GPS/GLONASS/Galileo receiver",
    };
    return d;
}

} // namespace gnss::geostar
