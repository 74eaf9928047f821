#pragma once
// Dialect: everything the program knows about one receiver family, as one constant record.
//
// A new receiver family is one folder (its messages, decoders, encoders, schema, reply rules)
// plus one line in protocol/builtin/dialects.cpp (and its simulated receiver, when it has one,
// a row in protocol/builtin/simulators.cpp): the record knows no simulator. Nothing else names
// vendors: not the decoder, not the views (docs/adding-a-dialect.md).
#include "core/fix_type.h"
#include "core/function_ref.h"
#include "core/message.h"
#include "core/satellite.h"
#include "core/sentence.h"
#include "core/settings_schema.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gnss {

struct Dialect;
struct ReceiverState;

// Passed to every decode function.
class DecodeContext {
public:
    using Emit = FunctionRef<void(const Message &)>;
    // Inline: built once per sentence, its FunctionRef (80 bytes) is then made in place rather
    // than written piecewise and copied whole (a store-forwarding stall on every sentence).
    inline DecodeContext(const Dialect *dialect, Emit onMessage);

    // The dialect in force (chosen, or detected so far); nullptr when none is known yet.
    const Dialect *dialect() const { return dialect_; }
    // Satellite numbering, with the dialect's override where it has one.
    SatelliteRef mapSatellite(Constellation system, int id) const {
        if (dialectMapsSatellites_) return mapSatelliteByDialect(system, id);
        return mapSatelliteIdInline(system, id);
    }
    // Hands the decoded message to the caller (valid only during the call).
    void deliver(const Message &m) { emit_(m); }

    // Why decoding failed (set by the decode function when it returns false), and the same as
    // a translatable refusal when the decoder gave one (fail()).
    std::string error;
    Refusal problem;
    void fail(Refusal why) {
        error = why.text;
        problem = std::move(why);
    }

private:
    SatelliteRef mapSatelliteByDialect(Constellation system, int id) const;
    const Dialect *dialect_;
    bool dialectMapsSatellites_ = false;
    Emit emit_;
};

// Decodes one sentence; calls ctx.emit() with the message and returns true, or sets ctx.error
// and returns false. Must not throw.
using DecodeFn = bool (*)(const Sentence &, DecodeContext &);

enum class AddressMatch : std::uint8_t {
    Whole, // the whole address: "PNVGRTK", "GPSGG", "PNMRX110"
    Type,  // talker + this type: "GGA" matches GPGGA, GNGGA, GLGGA, ...
    Query, // "$ttllQ,..." (any 5-character address ending in Q)
};

// One row of a dialect's sentence table: a new sentence costs one row plus its decode function.
struct SentenceRule {
    std::string_view address;
    AddressMatch match;
    DecodeFn decode;
    std::string_view description;
};

// ---- Command replies, for the command queue -------------------------------------------------

enum class ReplyVerdict : std::uint8_t {
    NotMine,  // this sentence does not answer the command
    Partial,  // part of the answer; keep waiting (multi-sentence replies)
    Accepted, // the receiver took the command
    Refused,  // the receiver answered, and said no
};

// State kept by the queue across the sentences of one reply.
struct ReplyProgress {
    int received = 0; // sentences of the answer seen so far
    int expected = 0; // set by the rule when the answer says how many will come
};

enum class CommandEffect : std::uint8_t {
    None,
    ChangesBaud,     // the port speed changes after the reply
    ResetsReceiver,  // the receiver restarts (fix sequence starts again)
    ChangesProtocol, // the receiver leaves NMEA (e.g. switches to a binary protocol)
    ChangesOutput,   // the output list/rate changes
};

struct ReplyRule {
    // Which commands the rule covers: the command's address (and, when not empty, its first
    // field: "GPSGG" + "RQUERY"). An empty firstField covers every command with that address.
    std::string_view commandAddress;
    std::string_view firstField;
    // Classifies a received sentence against the command that was sent; nullptr means the
    // receiver sends no reply (the command counts as sent once written).
    ReplyVerdict (*classify)(const Sentence &command, const Sentence &reply,
                             ReplyProgress &progress);
    int timeoutMs = 1000;
    int retries = 2;
    CommandEffect effect = CommandEffect::None;
    std::string_view description; // what the reply looks like, for users and docs
};

// ---- Receiver-wide actions, presets, link speed ---------------------------------------------

enum class ReceiverAction : std::uint8_t {
    SaveToFlash,     // the settings in force survive a power cycle
    RestoreDefaults, // back to the factory settings
    ColdStart,
    WarmStart,
    HotStart,
};
// "save", "defaults", "cold", "warm", "hot" (command line, profiles).
std::string_view toString(ReceiverAction a);

// One action a receiver family offers, and the command that does it.
struct ActionDef {
    ReceiverAction action;
    std::string_view body;   // sentence body without '$' and checksum: "PNVGCFG,W"
    std::string_view label;  // "Save to flash" (translated where it is shown)
    std::string_view effect; // what it does, for the confirmation
};

// A named set of setting values for a common job; applying it is applying its values.
struct PresetValue {
    std::string_view key, value;
};
struct Preset {
    std::string_view name;
    std::string_view description;
    std::span<const PresetValue> values;
};

// The command that changes the speed of the port the host is on, by the start of its body
// ("PNVGRZA,1,"): the link follows it to the new speed; a speed change of another port must not
// move the link. The setting that holds the new speed has the PortSpeed role.
struct LinkSpeedCommand {
    std::string_view commandPrefix;
};

// ---- The dialect record ---------------------------------------------------------------------

struct Dialect {
    std::string_view id;          // "nvs", "geostar", "nemerix", "nmea"
    std::string_view displayName; // "NVS NV08C-RTK"
    std::span<const SentenceRule> rules;

    // Whether a sentence without checksum is acceptable (Nemerix makes it optional).
    bool checksumOptional = false;
    // The vendor's meanings of GGA quality; nullptr = standard NMEA.
    FixType (*ggaQuality)(int quality) = nullptr;
    // The vendor's meanings of RMC/GNS/GLL mode letters; nullptr = standard NMEA.
    FixType (*modeIndicator)(char mode) = nullptr;
    // A note shown beside the fix badge for a vendor's kind of fix ("GeoPath"), from the GGA
    // quality (-1 when none) and the best mode letter ('\0' when none); nullptr = no notes.
    std::string_view (*fixNote)(int ggaQuality, char mode) = nullptr;
    // Satellite numbering override; nullptr = standard NMEA.
    SatelliteRef (*mapSatellite)(Constellation system, int id) = nullptr;

    // Translates one of the dialect's messages into the vendor-neutral receiver state (RTK
    // status, attitude, time marks, identity, status reports); true when it used the message.
    bool (*updateState)(const Message &m, ReceiverState &state) = nullptr;

    // Settings and commands.
    std::span<const SettingDef> settings;
    std::span<const ReplyRule> replyRules;
    // (Sentences that write and read settings come from the rows' commands: settings_plan.h.)
    // The longest sentence the receiver takes, with its "\r\n" (NMEA 0183: 82). A longer command
    // is refused before anything is sent (refuseLongSentences).
    std::size_t maxSentenceLength = 82;
    // Setting values carried by a decoded reply (read-back), appended to `out`.
    void (*extractSettings)(const Message &reply, std::vector<KeyValue> &out) = nullptr;

    // Probe for active detection: a command the receiver answers with its identity.
    std::string_view probeCommand;
    // Command names the console offers to complete ("PNVGRTK", "GPSGG,RQUERY", ...).
    std::span<const std::string_view> commandNames;
    // The example the console's send box shows: a harmless command this receiver answers.
    std::string_view consoleExample;
    // Default serial speed of the receiver, and every speed its ports can be set to.
    int defaultBaud = 0;
    // A proprietary prefix the user may rename on the receiver ("PNMRX"); empty when fixed.
    std::string_view renamablePrefix;
    std::span<const int> supportedBauds;

    // Receiver-wide actions (save, defaults, restarts), presets, the host port's speed command.
    std::span<const ActionDef> actions;
    std::span<const Preset> presets;
    LinkSpeedCommand linkSpeed;

    // One line for command-line help: "NVS NV08C-RTK (PNVG...): RTK rover and base".
    std::string_view summary;
    // Names an earlier version of the workbench gave a model, with the name it has now (a
    // profile saved under the old one is still for that model).
    std::span<const std::pair<std::string_view, std::string_view>> formerModelNames;
};

// The action of this kind a dialect offers, nullptr when it has none.
const ActionDef *findAction(const Dialect &d, ReceiverAction action);

inline DecodeContext::DecodeContext(const Dialect *dialect, Emit onMessage)
    : dialect_(dialect), dialectMapsSatellites_(dialect && dialect->mapSatellite),
      emit_(onMessage) {}

} // namespace gnss
