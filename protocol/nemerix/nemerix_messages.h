#pragma once
// Nemerix VT002 proprietary sentences ($PNMRXnnn) as small typed structs, one decoder per
// sentence (field diagram above each decoder in nemerix_<topic>.cpp).
//
// Commands (receiver input) decode too, so the console can show what was sent and the simulator
// can read what it receives. Text fields are views into the sentence: valid during emit() only.
#include "core/dialect.h"
#include "core/field_reader.h"
#include "core/finish_decode.h"
#include "core/message.h"
#include "nemerix/nemerix_hex.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace gnss::nemerix {

// The NMEA messages the VT002 outputs, in the order of PNMRX103's table (and of the delays in
// PNMRX603 message 0), and the Nemerix messages PNMRX107 controls.
inline constexpr std::array<std::string_view, 7> kNmeaMessageIds = {"GGA", "GLL", "GSA", "GSV",
                                                                    "RMC", "VTG", "ZDA"};
inline constexpr std::array<std::string_view, 5> kNavDataMessageIds = {"300", "301", "302", "303",
                                                                       "304"};

// ---- Commands -------------------------------------------------------------------------------

// PNMRX100: serial port (protocol, baud, parity).
struct SerialPort : Message {
    static const MessageType kType;
    SerialPort() : Message(kType) {}
    std::optional<int> protocol; // 0 NMEA, 1 Nemerix binary
    std::optional<int> baud;
    std::optional<int> parity; // 0 none, 1 odd, 2 even
    void writeJson(JsonWriter &w) const override;
};

// The fields PNMRX101 and PNMRX104 end with.
struct NavInitTail {
    std::optional<int> clockOffset; // Hz x 100 w.r.t. L1
    std::optional<int> timeOfWeek;  // s
    std::optional<int> week;
    std::optional<int> channels; // maximum number of tracking modules, 12..16
};

// PNMRX101: navigation initialisation (ECEF).
struct NavInit : Message, NavInitTail {
    static const MessageType kType;
    NavInit() : Message(kType) {}
    std::optional<std::int64_t> x, y, z; // ECEF metres
    // Fix procedure code: not in the field table, only in the examples ("$PNMRX101, 4," cold
    // start; "$PNMRX101,,,,,,,,,8," factory reset).
    std::optional<int> fixProcedure;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX104: navigation initialisation (latitude, longitude, altitude).
struct LlaInit : Message, NavInitTail {
    static const MessageType kType;
    LlaInit() : Message(kType) {}
    std::optional<double> lat, lon; // signed degrees
    std::optional<int> altitude;    // metres above MSL
    void writeJson(JsonWriter &w) const override;
};

// A (name, value) pair of PNMRX103 / PNMRX107.
struct RateEntry {
    std::string_view id; // "GGA", "ALL", "300"
    std::optional<int> value;
};

// PNMRX103 (NMEA output rates) and PNMRX107 (Nemerix message modes) share this shape.
struct RateList : Message {
    static const MessageType kNmeaType;    // PNMRX103
    static const MessageType kNemerixType; // PNMRX107
    static constexpr std::size_t kMax = 16;
    explicit RateList(const MessageType &t) : Message(t) {}
    std::array<RateEntry, kMax> entries{};
    std::size_t count = 0;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX108: NMEA output sequence.
struct NmeaSequence : Message {
    static const MessageType kType;
    static constexpr std::size_t kMax = 8;
    NmeaSequence() : Message(kType) {}
    std::array<std::string_view, kMax> ids{};
    std::size_t count = 0;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX106: map datum.
struct DatumSetting : Message {
    static const MessageType kType;
    DatumSetting() : Message(kType) {}
    std::optional<int> correction;                   // 1 = EGM96 geoid correction
    std::optional<int> datum;                        // 0-218 internal table, 500 user defined
    std::optional<int> dx, dy, dz;                   // metres
    std::optional<std::int64_t> iflatRaw, majorARaw; // as sent
    std::optional<double> inverseFlattening() const; // 290 + raw / 1e6
    std::optional<double> semiMajorAxis() const;     // 6370000 + raw / 1000 metres
    void writeJson(JsonWriter &w) const override;
};

// One PNMRX110 mask.
struct FixMask {
    int id = -1;
    std::string_view text;        // value as sent
    std::optional<double> value;  // engineering units (DOP /10 applied)
    std::optional<int> tzMinutes; // mask 0: signed offset in minutes
};

// PNMRX110: fix settings (mask id, value pairs).
struct FixSettings : Message {
    static const MessageType kType;
    static constexpr std::size_t kMax = 16;
    FixSettings() : Message(kType) {}
    std::array<FixMask, kMax> masks{};
    std::size_t count = 0;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX111: software reset.
struct SoftwareReset : Message {
    static const MessageType kType;
    SoftwareReset() : Message(kType) {}
    std::optional<int> bits; // invalidate bit field
    std::string_view named;  // FACTORY, COLD, WARM, HOT
    void writeJson(JsonWriter &w) const override;
};

// PNMRX112: operating (power) mode.
struct PowerMode : Message {
    static const MessageType kType;
    PowerMode() : Message(kType) {}
    std::optional<int> mode;      // 0 fully active, 1 LDCM1
    std::optional<int> offPeriod; // s, 5..10
    void writeJson(JsonWriter &w) const override;
};

// Commands without fields: PNMRX113 (stop GPS core), PNMRX601 (ISP mode), and the requests
// PNMRX600 / PNMRX603 (a PNMRX600/603 with fields is the receiver's report instead).
struct PlainCommand : Message {
    static const MessageType kStopCoreType;      // PNMRX113
    static const MessageType kIspType;           // PNMRX601
    static const MessageType kVersionQueryType;  // PNMRX600 request
    static const MessageType kSettingsQueryType; // PNMRX603 request
    explicit PlainCommand(const MessageType &t) : Message(t) {}
    void writeJson(JsonWriter &w) const override;
};

// ---- Navigation data (PNMRX300-304) ----------------------------------------------------------

// PNMRX300: almanac of one satellite (output, and upload to the receiver).
struct Almanac : Message {
    static const MessageType kType;
    enum Field {
        E,
        Health,
        Toa,
        DeltaI,
        OmegaDot,
        SqrtA,
        Omega0,
        Perigee,
        Mean,
        M0,
        Af0,
        Af1,
        kFieldCount
    };
    static std::span<const HexFieldDef> fields();
    Almanac() : Message(kType) {}
    int sv = 0;
    std::array<std::optional<std::int64_t>, kFieldCount> raw{};
    std::optional<double> value(Field f) const { return valueOf(fields(), raw, f); }
    // The inverse of value(): engineering units → the raw word (IS-GPS-200 scale, rounded);
    // refused (nothing set) when it does not fit the field.
    Refusal setValue(Field f, double v) { return setValueOf(fields(), raw, f, v); }
    void writeJson(JsonWriter &w) const override;
};

// PNMRX301: one of the three ephemeris subframe messages of a satellite.
struct EphemerisSubframe : Message {
    static const MessageType kType;
    static constexpr std::size_t kMaxFields = 9;
    // Field order of each subframe message (index into raw).
    enum Sf1 { WeekNumber, SvHealth, Ura, Tgd, Iodc, Toc, Af2, Af1, Af0 };
    enum Sf2 { Iode2, Crs, DeltaN, M0, Cuc, Ecc, Cus, SqrtA, Toe };
    enum Sf3 { Cic, Omega0, Cis, I0, Crc, Omega, OmegaDot, Iode3, Idot };
    static std::span<const HexFieldDef> fields(int subframe); // subframe 1..3
    EphemerisSubframe() : Message(kType) {}
    int sv = 0;
    int subframe = 0;
    std::array<std::optional<std::int64_t>, kMaxFields> raw{};
    std::optional<double> value(int field) const;
    Refusal setValue(int field, double v); // the inverse of value(), as Almanac::setValue
    void writeJson(JsonWriter &w) const override;
};

// PNMRX302 and PNMRX303: the satellite's id (optional) and the N packed words of M::fields();
// the JSON is the id, then every word (writeHexFields).
template <class M, std::size_t N> struct SvHexWords : Message {
    SvHexWords() : Message(M::kType) {}
    std::optional<int> sv;
    std::array<std::optional<std::int64_t>, N> raw{};
    void writeJson(JsonWriter &w) const override {
        w.beginObject().field("sv", sv);
        writeHexFields(w, M::fields(), raw);
        w.endObject();
    }
};

// PNMRX302: ionospheric (Klobuchar) coefficients.
struct Ionosphere : SvHexWords<Ionosphere, 8> {
    static const MessageType kType;
    static std::span<const HexFieldDef> fields(); // alpha0-3, beta0-3
    std::optional<double> value(int field) const {
        return valueOf(fields(), raw, static_cast<std::size_t>(field));
    }
    // The inverse of value(), as Almanac::setValue.
    Refusal setValue(int field, double v) {
        return setValueOf(fields(), raw, static_cast<std::size_t>(field), v);
    }
};

// PNMRX303: GPS-UTC parameters.
struct UtcParameters : SvHexWords<UtcParameters, 10> {
    static const MessageType kType;
    enum Field { A0, A1, DtLs, Tot, WnT, WnLsf, Dn, DtLsf, NumBlocks, TimeOffset, kFieldCount };
    static_assert(std::tuple_size_v<decltype(raw)> == kFieldCount);
    static std::span<const HexFieldDef> fields();
    std::optional<double> value(Field f) const { return valueOf(fields(), raw, f); }
    // The inverse of value(), as Almanac::setValue.
    Refusal setValue(Field f, double v) { return setValueOf(fields(), raw, f, v); }
};

// PNMRX304: constellation health; the spec leaves the fields "TBD": kept raw.
struct ConstellationHealth : Message {
    static const MessageType kType;
    static constexpr std::size_t kMax = 64;
    ConstellationHealth() : Message(kType) {}
    std::array<std::string_view, kMax> codes{};
    std::size_t count = 0;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX600 (software version) / PNMRX602 (flash content version) reports: the spec gives no
// field layout, so the fields are shown as sent.
struct VersionReport : Message {
    static const MessageType kSoftwareType; // PNMRX600 with fields
    static const MessageType kFlashType;    // PNMRX602
    static constexpr std::size_t kMax = 16;
    explicit VersionReport(const MessageType &t) : Message(t) {}
    std::array<std::string_view, kMax> fieldsText{};
    std::size_t count = 0;
    void writeJson(JsonWriter &w) const override;
};

// PNMRX603: settings report, messages 0 to 4.
struct SettingsReport : Message {
    static const MessageType kType;
    SettingsReport() : Message(kType) {}
    int number = -1; // message number 0..4
    // Message 0
    std::array<std::optional<int>, 7> sequence{}; // layout not documented: as sent
    std::array<std::optional<int>, 7>
            delay{}; // per NMEA message, in GGA GLL GSA GSV RMC VTG ZDA order (inferred)
    std::optional<std::uint64_t> nmrxEnabled, uartSettings; // 32-bit words, layout not documented
    // Message 1
    std::array<std::optional<std::int64_t>, 8> iono{}; // same scales as PNMRX302
    std::optional<std::uint64_t> ionoValid, numBlocks;
    std::optional<int> tzHours, tzMinutes;
    // Message 2
    std::optional<double> maxPdop, maxHdop, minCno, minElevation;
    std::optional<std::uint64_t> invalidSv; // bit n-1 = SV n excluded
    std::optional<int> maxTm, maxSvForFix;
    // Message 3
    std::optional<std::int64_t> acqThreshold1, acqThreshold2, noiseFloor, defaultAltitude;
    std::optional<std::uint64_t> kalmanMode;
    // Message 4
    std::optional<int> correction, datum;
    std::optional<std::int64_t> dx, dy, dz, iflatRaw, majorARaw;
    void writeJson(JsonWriter &w) const override;
};

// ---- Decoders -------------------------------------------------------------------------------
bool decodeSerialPort(const Sentence &s, DecodeContext &ctx);      // 100
bool decodeNavInit(const Sentence &s, DecodeContext &ctx);         // 101
bool decodeNmeaRates(const Sentence &s, DecodeContext &ctx);       // 103
bool decodeLlaInit(const Sentence &s, DecodeContext &ctx);         // 104
bool decodeDatum(const Sentence &s, DecodeContext &ctx);           // 106
bool decodeNemerixRates(const Sentence &s, DecodeContext &ctx);    // 107
bool decodeNmeaSequence(const Sentence &s, DecodeContext &ctx);    // 108
bool decodeFixSettings(const Sentence &s, DecodeContext &ctx);     // 110
bool decodeSoftwareReset(const Sentence &s, DecodeContext &ctx);   // 111
bool decodePowerMode(const Sentence &s, DecodeContext &ctx);       // 112
bool decodeStopCore(const Sentence &s, DecodeContext &ctx);        // 113
bool decodeAlmanac(const Sentence &s, DecodeContext &ctx);         // 300
bool decodeEphemeris(const Sentence &s, DecodeContext &ctx);       // 301
bool decodeIonosphere(const Sentence &s, DecodeContext &ctx);      // 302
bool decodeUtc(const Sentence &s, DecodeContext &ctx);             // 303
bool decodeHealth(const Sentence &s, DecodeContext &ctx);          // 304
bool decodeSoftwareVersion(const Sentence &s, DecodeContext &ctx); // 600
bool decodeIsp(const Sentence &s, DecodeContext &ctx);             // 601
bool decodeFlashVersion(const Sentence &s, DecodeContext &ctx);    // 602
bool decodeSettingsReport(const Sentence &s, DecodeContext &ctx);  // 603

// Names of the PNMRX110 masks, by id (nullptr past the table).
const char *fixMaskName(int id);
// Parses a PNMRX110 time zone "h:m" ("-2:0", "+5:30", "-0:30") into signed minutes.
std::optional<int> parseTimeZone(std::string_view text);

} // namespace gnss::nemerix
