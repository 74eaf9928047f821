#pragma once
// NVS NV08C-RTK proprietary sentences (nvs-nv08c-rtk-nmea-v1.6.txt, chapter 4) as small typed
// structs. Empty fields are std::nullopt. Each decoder and its field diagram live in nvs_<x>.cpp
// (a sentence that is a plain list of fields is a FieldMessage, core/field_table.h: its rows there
// decode it, write its JSON and, for what the receiver sends, encode it); sentences that are both
// command and reply decode into one struct (the console shows what was sent, the simulator reads
// what it receives).
#include "core/decode_with.h"
#include "core/dialect.h"
#include "core/field_reader.h"
#include "core/field_table.h"
#include "core/field_types.h"
#include "core/finish_decode.h"
#include "core/message.h"
#include "nmea/nmea_messages.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::nvs {

// 4.1 PNVGVER: the request has no fields; the reply names manufacturer, device and firmware.
struct Ver : FieldMessage<Ver> {
    static const MessageType kType;
    static const FieldRow<Ver> kFields[5];
    bool request = false;                         // "$PNVGVER" without fields
    std::optional<std::string_view> manufacturer; // "NVS"
    std::optional<std::string_view> device;       // "RTK" (NV08C-RTK) or "RTA" (NV08C-RTK-A)
    std::optional<std::string_view> rtkFw;        // "xxxx", kept as printed (leading zeros)
    std::optional<std::string_view> csmHw;        // "CSM24"
    std::optional<std::string_view> csmFw;
};

// 4.2 PNVGNME: NMEA output resolution and talker compatibility (command and reply).
struct Nme : FieldMessage<Nme> {
    static const MessageType kType;
    static const FieldRow<Nme> kFields[3];
    static constexpr std::size_t kRequired = 2;
    std::optional<int> timeDecimals;     // 0..6
    std::optional<int> positionDecimals; // 0..9
    std::optional<int> talkerMode;       // 0 GGA/RMC always "GP", 1 as specified (optional)
};

// 4.3 PNVGRST: reset (command only).
struct Rst : Message {
    static const MessageType kType;
    Rst() : Message(kType) {}
    std::optional<char> type; // F cold start, W warm restart
    void writeJson(JsonWriter &w) const override;
};

// 4.4 PNVGRZA: COM port protocol and speed (command and reply).
struct Rza : FieldMessage<Rza> {
    static const MessageType kType;
    static const FieldRow<Rza> kFields[3];
    static constexpr std::size_t kRequired = 3;
    std::optional<int> port;     // 0 current, 1 COM1, 2 COM2, 3 USB
    std::optional<int> baud;     // 4800..460800
    std::optional<int> protocol; // 0 disabled, 1 NMEA, 7 RTCM
};

// 4.5 PNVGRZB: output list (clear, or add messages with rates; optionally for one port).
struct RzbEntry {
    std::string address; // "RMC", "PNVGTST"
    int rate = 1;        // in PVT update intervals
};
struct Rzb : Message {
    static const MessageType kType;
    Rzb() : Message(kType) {}
    std::optional<int> port;       // "PORT,x"; nullopt = current port
    std::vector<RzbEntry> entries; // empty = clear the list
    void writeJson(JsonWriter &w) const override;
};

// 4.6 PNVGBSS: base station statistics.
struct Bss : FieldMessage<Bss> {
    static const MessageType kType;
    static const FieldRow<Bss> kFields[5];
    static constexpr std::size_t kRequired = 4;
    std::optional<std::int64_t> rtcmTotal, rtcmErrors, rtcmOk;
    std::optional<double> baseDistance; // metres
    std::optional<double> rtcmAge;      // seconds; blank until the first RTCM message
};

// 4.7 PNVGTST: internal test results, name/result pairs (ID, ANT).
struct TstItem {
    std::string_view name, result;
};
struct Tst : Message {
    static const MessageType kType;
    Tst() : Message(kType) {}
    std::vector<TstItem> tests;
    std::optional<std::int64_t> deviceId; // ID test
    std::optional<int> antenna;           // ANT test: 0 connected, 1 no antenna, 2 short circuit
    void writeJson(JsonWriter &w) const override;
};

// 4.8 PNVGCFG: save/erase settings (command and confirming reply).
struct Cfg : Message {
    static const MessageType kType;
    Cfg() : Message(kType) {}
    std::string_view action;             // W save, E erase, R erase and restart
    std::vector<std::string_view> extra; // further fields of the reply, as received
    void writeJson(JsonWriter &w) const override;
};

// 4.9 PNVGPPS: time pulse (command with empty = unchanged fields, and reply).
struct Pps : FieldMessage<Pps> {
    static const MessageType kType;
    static const FieldRow<Pps> kFields[7];
    static constexpr std::size_t kRequired = 7;
    std::optional<char> type;      // P software-synchronised, A hardware-synchronised
    std::optional<char> mode;      // I interval, S 1PPS
    std::optional<char> reference; // U UTC, S UTC(SU), G GLONASS, N GPS
    std::optional<int> adjust;     // 1 on, 0 off
    std::optional<int> duration;   // microseconds, 1..1000
    std::optional<char> validity;  // E enabled, D disabled
    std::optional<int> cableDelay; // nanoseconds
};

// 4.10 PNVGIMU: attitude and NED acceleration. Firmware before 1.5 sends no time tag.
struct Imu : FieldMessage<Imu> {
    static const MessageType kType;
    static const FieldRow<Imu> kFields[7];
    std::optional<TimeOfDay> time;
    std::optional<double> roll, pitch, yaw;           // degrees
    std::optional<double> accNorth, accEast, accDown; // m/s^2
};

// 4.11 PNVGBRS (base-to-rover) and 4.12 PNVGBLS (ANT1-ANT2 base-line; no time tag before 1.5).
struct Baseline : Message {
    explicit Baseline(const MessageType &t) : Message(t) {}
    std::optional<TimeOfDay> time;
    std::optional<double> north, east, vertical, length; // metres
    std::optional<double> course, pitch;                 // degrees
    std::optional<char> mode;                            // A D F R E N
    void writeJson(JsonWriter &w) const override;
};
struct Brs : Baseline {
    static const MessageType kType;
    Brs() : Baseline(kType) {}
};
struct Bls : Baseline {
    static const MessageType kType;
    Bls() : Baseline(kType) {}
};

// 4.13 PNVGVOG: velocity over ground.
struct Vog : FieldMessage<Vog> {
    static const MessageType kType;
    static const FieldRow<Vog> kFields[5];
    static constexpr std::size_t kRequired = 5;
    std::optional<TimeOfDay> time;
    std::optional<double> velNorth, velEast, velUp; // m/s
    std::optional<char> mode;
};

// 4.14 PNVGRTK: any mix of parameters; a parameter with values is set (or reported), one
// without values is queried.
struct RtkParam {
    std::string_view name;
    std::vector<std::string_view> values; // empty = query
};
struct Rtk : Message {
    static const MessageType kType;
    Rtk() : Message(kType) {}
    std::vector<RtkParam> params;
    const RtkParam *find(std::string_view name) const;
    void writeJson(JsonWriter &w) const override;
};

// 4.15 PNVGIDL: the known base station list.
enum class IdlKind { Mode, Add, Remove, Clear, Show, Item };
std::string_view toString(IdlKind k);
struct Idl : Message {
    static const MessageType kType;
    Idl() : Message(kType) {}
    IdlKind kind = IdlKind::Show;
    std::optional<int> mode;         // MODE: 0 any station, 1 listed stations only
    std::optional<int> stationId;    // ADD, REMOVE (command), Item
    std::optional<double> icb;       // ADD, Item: GLONASS inter-channel bias
    bool ok = false;                 // REMOVE,OK / CLEAR,OK replies
    std::string_view status;         // REMOVE/CLEAR reply word as received ("OK")
    std::optional<int> count, index; // Item: list length, 1-based index
    void writeJson(JsonWriter &w) const override;
};

// 4.16 PNVGTME / 4.17 PNVGTMU: time mark event (TOW / UTC).
struct Tme : FieldMessage<Tme> {
    static const MessageType kType;
    static const FieldRow<Tme> kFields[2];
    static constexpr std::size_t kRequired = 2;
    std::optional<std::int64_t> counter;
    std::optional<double> tow; // seconds of GPS week
};
struct Tmu : FieldMessage<Tmu> {
    static const MessageType kType;
    static const FieldRow<Tmu> kFields[2];
    static constexpr std::size_t kRequired = 2;
    std::optional<std::int64_t> counter;
    std::optional<TimeOfDay> time;
};

// 4.18 PNVGTMC: GGA-like fix at the time mark (kept apart from GGA: it is not the epoch's fix).
// The GGA layout at the event (quality with NVS GGA meanings: 4 RTK fixed, 5 float, 6 estimated).
struct Tmc : Message, nmea::GgaFields {
    static const MessageType kType;
    Tmc() : Message(kType) {}
    void writeJson(JsonWriter &w) const override { nmea::writeGgaFieldsJson(w, *this); }
};

// 4.19-4.21 PNVGSDP / PNVGSDV / PNVGSDH: standard deviations.
struct Sdp : FieldMessage<Sdp> {
    static const MessageType kType;
    static const FieldRow<Sdp> kFields[5];
    static constexpr std::size_t kRequired = 5;
    std::optional<TimeOfDay> time;
    std::optional<double> sdLat, sdLon, sdHeight; // metres
    std::optional<char> mode;
};
struct Sdv : FieldMessage<Sdv> {
    static const MessageType kType;
    static const FieldRow<Sdv> kFields[5];
    static constexpr std::size_t kRequired = 5;
    std::optional<TimeOfDay> time;
    std::optional<double> sdVelNorth, sdVelEast, sdVelUp; // m/s
    std::optional<char> mode;
};
struct Sdh : FieldMessage<Sdh> {
    static const MessageType kType;
    static const FieldRow<Sdh> kFields[3];
    static constexpr std::size_t kRequired = 3;
    std::optional<TimeOfDay> time;
    std::optional<double> sdHeading; // degrees
    std::optional<char> mode;
};

// 4.22 PNVGDOP (the spec's field table calls its address PNVGSDH: a copy-paste typo,
// docs/spec-notes.md).
struct Dop : FieldMessage<Dop> {
    static const MessageType kType;
    static const FieldRow<Dop> kFields[9];
    static constexpr std::size_t kRequired = 9;
    std::optional<TimeOfDay> time;
    std::optional<double> gdop, pdop, hdop, vdop, tdop, ndop, edop;
    std::optional<char> mode;
};

bool decodeVer(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeNme = decodeMessage<Nme>;
bool decodeRst(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeRza = decodeMessage<Rza>;
bool decodeRzb(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeBss = decodeMessage<Bss>;
bool decodeTst(const Sentence &, DecodeContext &);
bool decodeCfg(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodePps = decodeMessage<Pps>;
bool decodeImu(const Sentence &, DecodeContext &);
bool decodeBrs(const Sentence &, DecodeContext &);
bool decodeBls(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeVog = decodeMessage<Vog>;
bool decodeRtk(const Sentence &, DecodeContext &);
bool decodeIdl(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeTme = decodeMessage<Tme>;
inline constexpr DecodeFn decodeTmu = decodeMessage<Tmu>;
bool decodeTmc(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeSdp = decodeMessage<Sdp>;
inline constexpr DecodeFn decodeSdv = decodeMessage<Sdv>;
inline constexpr DecodeFn decodeSdh = decodeMessage<Sdh>;
inline constexpr DecodeFn decodeDop = decodeMessage<Dop>;

// The NVS sentence table (every PNVG* address, whole-address rules).
std::span<const SentenceRule> sentenceRules();

// Writes a field value: integer or real as a JSON number when it is one, else as a string.
void writeValue(JsonWriter &w, std::string_view text);

} // namespace gnss::nvs
