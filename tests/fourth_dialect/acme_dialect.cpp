// The ACME AX-1 record and everything it holds (see acme_dialect.h): sentences, the settings
// schema with its commands, reply rules, actions, presets, the receiver state it feeds.
#include "acme_dialect.h"

#include "core/decode_with.h"
#include "core/sentence_builder.h"
#include "core/setting_command.h"
#include "state/receiver_state.h"
#include "state/report_json.h"

namespace gnss::acme {

const MessageType Status::kType{"PACMS"};
const MessageType Version::kType{"PACMV"};
const MessageType Setting::kType{"PACMC"};
const MessageType Action::kType{"PACMA"};

const FieldRow<Status> Status::kFields[] = {
        {&Status::fix, "fix", "fix"},
        {&Status::used, "used", "used"},
        {&Status::temperature, "temperature", "temperature"},
};

void Version::writeJson(JsonWriter &w) const {
    w.beginObject().field("model", model).field("firmware", firmware).endObject();
}

void Setting::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("kind", std::string_view(&kind, 1))
            .field("name", name)
            .field("value", value)
            .endObject();
}

void Action::writeJson(JsonWriter &w) const {
    w.beginObject().field("action", what).field("ok", ok).endObject();
}

std::string encodeStatus(const Status &m) {
    auto opt = [](const auto &v, auto f) { return v ? f(*v) : std::string(); };
    return buildSentence("PACMS," + opt(m.fix, [](int x) { return std::to_string(x); }) + "," +
                         opt(m.used, [](int x) { return std::to_string(x); }) + "," +
                         opt(m.temperature, [](double x) { return formatFixed(x, 1); }));
}

std::string encodeVersion(const Version &m) {
    if (m.request) return buildSentence("PACMV");
    return buildSentence("PACMV," + std::string(m.model.value_or("")) + "," +
                         std::string(m.firmware.value_or("")));
}

std::string encodeAction(const Action &m) {
    return buildSentence("PACMA," + std::string(m.what) + (m.ok ? ",OK" : ""));
}

std::string encodeRefusal(std::string_view name) {
    return buildSentence("PACMN," + std::string(name));
}

namespace {

// ---- Decoders -------------------------------------------------------------------------------

bool decodeVersion(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Version m;
    m.request = s.fieldCount() == 0;
    if (!m.request && r.require(2)) {
        m.model = r.str(0);
        m.firmware = r.str(1);
    }
    return finishDecode(r, ctx, m);
}

bool decodeSetting(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Setting>(s, ctx, 1, [&s](FieldReader &r, Setting &m) {
        m.kind = s.address().back();
        m.name = r.text(0);
        if (m.kind == 'C' && r.require(2)) m.value = r.text(1);
    });
}

bool decodeAction(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Action>(s, ctx, 1, [](FieldReader &r, Action &m) {
        m.what = r.text(0);
        m.ok = r.text(1) == "OK";
    });
}

constexpr SentenceRule kRules[] = {
        {"PACMS", AddressMatch::Whole, decodeMessage<Status>, "ACME status"},
        {"PACMV", AddressMatch::Whole, decodeVersion, "ACME identity (request and reply)"},
        {"PACMC", AddressMatch::Whole, decodeSetting, "ACME setting: set, or its value"},
        {"PACMQ", AddressMatch::Whole, decodeSetting, "ACME setting read"},
        {"PACMN", AddressMatch::Whole, decodeSetting, "ACME setting refused"},
        {"PACMA", AddressMatch::Whole, decodeAction, "ACME action"},
};

// ---- Settings -------------------------------------------------------------------------------

std::string_view nameOf(std::string_view key) {
    return key.substr(key.find('.') + 1);
}

EncodeResult writeSettings(std::span<const KeyValue> values) {
    EncodeResult r;
    for (const auto &kv : values)
        r.sentences.push_back(
                buildSentence("PACMC," + std::string(nameOf(kv.key)) + "," + kv.value));
    return r;
}

EncodeResult readSettings(std::span<const std::string> keys) {
    EncodeResult r;
    for (const auto &k : keys)
        r.sentences.push_back(buildSentence("PACMQ," + std::string(nameOf(k))));
    return r;
}

void extractSettings(const Message &m, std::vector<KeyValue> &out) {
    if (const auto *s = message_cast<Setting>(m); s && s->kind == 'C' && s->value)
        out.push_back({"acme." + std::string(s->name), std::string(*s->value)});
}

constexpr SettingCommand kSettingCommand{
        .name = "PACMC", .write = writeSettings, .read = readSettings};
constexpr SettingCommand kBaudCommand{
        .name = "PACMC,BAUD", .changesLink = true, .write = writeSettings, .read = readSettings};

constexpr SettingOption kRates[] = {{"1", "1 Hz"}, {"5", "5 Hz"}, {"10", "10 Hz"}};
constexpr SettingOption kBauds[] = {{"9600", "9600"}, {"38400", "38400"}, {"115200", "115200"}};
constexpr int kBaudRates[] = {9600, 38400, 115200};

constexpr SettingDef kSchema[] = {
        {.key = "acme.RATE",
         .label = "Output rate",
         .group = "Output",
         .type = SettingType::Enum,
         .unit = "Hz",
         .options = kRates,
         .defaultValue = "1",
         .help = "Navigation epochs per second.",
         .readBack = "$PACMQ,RATE -> $PACMC,RATE,<value>",
         .write = "$PACMC,RATE,<value>",
         .command = &kSettingCommand,
         .role = SettingRole::OutputRate},
        {.key = "acme.ELEV",
         .label = "Elevation mask",
         .group = "Navigation",
         .type = SettingType::Integer,
         .unit = "deg",
         .min = 0,
         .max = 60,
         .defaultValue = "10",
         .help = "Satellites below the mask are not used.",
         .readBack = "$PACMQ,ELEV -> $PACMC,ELEV,<value>",
         .write = "$PACMC,ELEV,<value>",
         .command = &kSettingCommand,
         .role = SettingRole::ElevationMask},
        {.key = "acme.BAUD",
         .label = "Baud rate",
         .group = "Port",
         .type = SettingType::Enum,
         .unit = "bit/s",
         .options = kBauds,
         .defaultValue = "38400",
         .help = "The port's speed; it changes once the receiver has answered.",
         .readBack = "$PACMQ,BAUD -> $PACMC,BAUD,<value>",
         .write = "$PACMC,BAUD,<value>",
         .command = &kBaudCommand,
         .role = SettingRole::PortSpeed},
};

// ---- Replies --------------------------------------------------------------------------------

using V = ReplyVerdict;

V classifyVersion(const Sentence &, const Sentence &reply, ReplyProgress &) {
    return reply.address() == "PACMV" && reply.fieldCount() >= 2 ? V::Accepted : V::NotMine;
}

// PACMC is echoed with the value in force (another value: not taken); PACMN refuses it.
V classifySetting(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    if (reply.fieldCount() < 1 || reply.field(0) != command.field(0)) return V::NotMine;
    if (reply.address() == "PACMN") return V::Refused;
    if (reply.address() != "PACMC" || reply.fieldCount() < 2) return V::NotMine;
    if (command.address() == "PACMQ") return V::Accepted;
    return reply.field(1) == command.field(1) ? V::Accepted : V::Refused;
}

V classifyAction(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    if (reply.address() != "PACMA" || reply.field(0) != command.field(0)) return V::NotMine;
    return reply.field(1) == "OK" ? V::Accepted : V::Refused;
}

constexpr ReplyRule kReplyRules[] = {
        {"PACMV", "", classifyVersion, 1000, 2, CommandEffect::None, "PACMV,<model>,<firmware>"},
        {"PACMC", "BAUD", classifySetting, 1000, 2, CommandEffect::ChangesBaud,
         "PACMC echoed, then the port changes speed"},
        {"PACMC", "RATE", classifySetting, 1000, 2, CommandEffect::ChangesOutput,
         "PACMC echoed with the value in force, or PACMN"},
        {"PACMC", "", classifySetting, 1000, 2, CommandEffect::None,
         "PACMC echoed with the value in force, or PACMN"},
        {"PACMQ", "", classifySetting, 1000, 2, CommandEffect::None, "PACMC with the value"},
        {"PACMA", "COLD", classifyAction, 1000, 2, CommandEffect::ResetsReceiver, "PACMA,COLD,OK"},
        {"PACMA", "HOT", classifyAction, 1000, 2, CommandEffect::ResetsReceiver, "PACMA,HOT,OK"},
        {"PACMA", "", classifyAction, 2000, 1, CommandEffect::None, "PACMA,<action>,OK"},
};

// ---- Actions, presets, state ----------------------------------------------------------------

constexpr ActionDef kActions[] = {
        {ReceiverAction::SaveToFlash, "PACMA,SAVE", "Save to flash",
         "The settings in force survive a power cycle."},
        {ReceiverAction::RestoreDefaults, "PACMA,DEFAULTS", "Factory defaults",
         "The factory settings come back at the next power cycle."},
        {ReceiverAction::ColdStart, "PACMA,COLD", "Cold start", "Everything learnt is dropped."},
        {ReceiverAction::HotStart, "PACMA,HOT", "Hot start", "The engine restarts."},
};

constexpr PresetValue kFast[] = {{"acme.RATE", "10"}};
constexpr PresetValue kHighMask[] = {{"acme.ELEV", "25"}, {"acme.RATE", "1"}};
constexpr Preset kPresets[] = {
        {"Fast output", "10 epochs a second", kFast},
        {"Urban canyon", "A high elevation mask, one epoch a second", kHighMask},
};

constexpr std::string_view kCommandNames[] = {"PACMV", "PACMC", "PACMQ", "PACMA"};

bool updateState(const Message &m, ReceiverState &st) {
    if (const auto *v = message_cast<Version>(m); v && !v->request) {
        st.identity.vendor = "ACME";
        st.identity.model = std::string(v->model.value_or(""));
        st.identity.firmware = std::string(v->firmware.value_or(""));
        st.reports["Version"] = messageJson(m);
        return true;
    }
    if (message_cast<Status>(m)) {
        st.reports["Status"] = messageJson(m);
        return true;
    }
    return false;
}

} // namespace

const Dialect &dialect() {
    // The probe's checksum is computed, not typed.
    static const std::string probe = buildSentence("PACMV");
    static const Dialect d{
            .id = "acme",
            .displayName = "ACME AX-1",
            .rules = kRules,
            .updateState = updateState,
            .settings = kSchema,
            .replyRules = kReplyRules,
            .extractSettings = extractSettings,
            .probeCommand = probe,
            .commandNames = kCommandNames,
            .consoleExample = "$PACMV",
            .defaultBaud = 38400,
            .supportedBauds = kBaudRates,
            .actions = kActions,
            .presets = kPresets,
            .linkSpeed = {"PACMC,BAUD,"},
            .summary = "ACME AX-1 (PACM...): a receiver family of the tests only",
    };
    return d;
}

} // namespace gnss::acme
