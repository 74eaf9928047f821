// The NVS NV08C-RTK dialect record: sentences, settings, commands and replies as one constant.
#include "nvs/nvs_dialect.h"
#include "core/sentence_builder.h"
#include "nvs/nvs_actions.h"
#include "nvs/nvs_state.h"

#include "nvs/nvs_messages.h"
#include "nvs/nvs_reply_rules.h"
#include "nvs/nvs_schema.h"

namespace gnss::nvs {

FixType ggaQuality(int quality) {
    switch (quality) {
    case 0: return FixType::None;
    case 1: return FixType::Fix3D; // autonomous (GSA refines 2D/3D)
    case 2: return FixType::Dgnss;
    case 4: return FixType::RtkFixed;
    case 5: return FixType::RtkFloat;
    case 6: return FixType::Estimated;
    default: return fixTypeFromGgaQuality(quality); // not used by NVS
    }
}

namespace {
constexpr std::string_view kCommands[] = {
        "PNVGVER", "PNVGNME", "PNVGRST", "PNVGRZA", "PNVGRZB",
        "PNVGCFG", "PNVGPPS", "PNVGRTK", "PNVGIDL", "GPGPQ",
};
// Before 2026-12-07 the heading receiver (device id RTA) was called "NV08C-RTA".
constexpr std::pair<std::string_view, std::string_view> kFormerModelNames[] = {
        {"NV08C-RTA", "NV08C-RTK-A"},
};
} // namespace

const Dialect &dialect() {
    // The probe's checksum is computed, not typed.
    static const std::string probe = buildSentence("PNVGVER");
    static const Dialect d{
            .id = "nvs",
            .displayName = "NVS NV08C-RTK",
            .rules = sentenceRules(),
            .ggaQuality = ggaQuality,
            .updateState = updateState,
            .settings = settingsSchema(),
            .replyRules = replyRules(),
            // Revision 1.4 lifted NMEA's 82-character limit (docs/spec-notes.md): a PNVGRTK
            // that sets many parameters at once is longer. Bounded all the same.
            .maxSentenceLength = 512,
            .extractSettings = extractSettings,
            .probeCommand = probe,
            .commandNames = kCommands,
            .consoleExample = "$PNVGVER",
            .defaultBaud = kDefaultBaud,
            .supportedBauds = kSupportedBauds,
            .actions = kActions,
            .presets = kPresets,
            .linkSpeed = {"PNVGRZA,1,"}, // the host is on COM1
            .summary = "NVS NV08C-RTK (PNVG...): RTK rover, base and heading receiver",
            .formerModelNames = kFormerModelNames,
    };
    return d;
}

} // namespace gnss::nvs
