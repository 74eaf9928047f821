// The Nemerix VT002 dialect record.
#include "nemerix/nemerix_dialect.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_actions.h"
#include "nemerix/nemerix_state.h"

#include "nemerix/nemerix_dialect_parts.h"

namespace gnss::nemerix {

namespace {
constexpr std::string_view kCommandNames[] = {
        "PNMRX100", "PNMRX101", "PNMRX103", "PNMRX104", "PNMRX106",
        "PNMRX107", "PNMRX108", "PNMRX110", "PNMRX111", "PNMRX112",
        "PNMRX113", "PNMRX300", "PNMRX600", "PNMRX601", "PNMRX603",
};
} // namespace

const Dialect &dialect() {
    // The probe's checksum is computed, not typed.
    static const std::string probe = buildSentence("PNMRX600");
    static const Dialect d{
            .id = "nemerix",
            .displayName = "Nemerix VT002",
            .rules = sentenceRules(),
            // The checksum is optional on every sentence (Appendix C, "General NMEA Format").
            .checksumOptional = true,
            .updateState = updateState,
            .settings = settingsSchema(),
            .replyRules = replyRules(),
            .extractSettings = extractSettings,
            // PNMRX600 with its real checksum (the spec prints *00).
            .probeCommand = probe,
            .commandNames = kCommandNames,
            .consoleExample = "$PNMRX600",
            // "9600 baud rate, 8 bits data, 1 start, 1 stop, no parity" (2.1.8).
            .defaultBaud = kDefaultBaud,
            // "The PNMRX part may be replaced by a configured alternative" (Extensions spec).
            .renamablePrefix = "PNMRX",
            .supportedBauds = kSupportedBauds,
            .actions = kActions,
            .presets = kPresets,
            .linkSpeed = {"PNMRX100,"},
            .summary = "Nemerix VT002 (PNMRX...): GPS module",
    };
    return d;
}

} // namespace gnss::nemerix
