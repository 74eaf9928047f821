// GeoStar GeoS-5: sentence table and the dialect record.
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_actions.h"
#include "geostar/geostar_state.h"

#include "geostar/geostar_gns.h"
#include "geostar/geostar_messages.h"
#include "geostar/geostar_numbering.h"
#include "geostar/geostar_reply_rules.h"
#include "geostar/geostar_schema.h"

#include "core/sentence_builder.h"
#include "core/settings_plan.h"

#include <string>
#include <vector>

namespace gnss::geostar {
namespace {

constexpr SentenceRule kRules[] = {
        {"GPSGG", AddressMatch::Whole, decodeSgg,
         "GeoS-5 proprietary: RQUERY/NQUERY replies, JAMDET and every input command"},
        {"RLM", AddressMatch::Type, decodeRlm, "Galileo return link message"},
        // Subsidiary per-system GNS (satellite count in the mode position), else standard GNS.
        {"GNS", AddressMatch::Type, decodeGns, "GNSS fix data (with GeoS-5 subsidiary sentences)"},
};

// The record without its console names: they are every command it can send (commandBodies),
// so they are made from it, never listed beside it.
Dialect recordWithoutNames() {
    // The probe's checksum is computed, not typed.
    static const std::string probe = buildSentence("GPSGG,RQUERY");
    return Dialect{
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
            .probeCommand = probe,
            .consoleExample = "$GPSGG,RQUERY",
            .defaultBaud = kDefaultBaud,
            .supportedBauds = kSupportedBauds,
            .actions = kActions,
            .presets = kPresets,
            .linkSpeed = {"GPSGG,BDR"},
            .summary = "GeoStar GeoS-5 ($GPSGG,...): GPS/GLONASS/Galileo receiver",
    };
}

} // namespace

const Dialect &dialect() {
    static const Dialect d = [] {
        Dialect r = recordWithoutNames();
        static const std::vector<std::string> bodies = commandBodies(r);
        static const std::vector<std::string_view> names(bodies.begin(), bodies.end());
        r.commandNames = names;
        return r;
    }();
    return d;
}

} // namespace gnss::geostar
