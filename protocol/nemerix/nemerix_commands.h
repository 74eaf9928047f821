#pragma once
// Encoders for every Nemerix command. Each returns an EncodeResult: the sentences to send
// ("$...*HH", correct checksum, no CR LF), or an error naming the parameter and the accepted
// range, in which case nothing is built.
//
// Renamed prefix: the receiver can be configured to use another string in place of "NMRX"
// (spec, "Extensions Specification"). Every encoder takes the address prefix as its last
// argument ("PNMRX" by default, e.g. "PXYZW"); applyPrefix() renames an already built sentence
// (e.g. the output of Dialect::encodeSettings) and recomputes its checksum. Decoding a renamed
// prefix uses DecoderOptions::addressAliases {"PXYZW", "PNMRX"}.
#include "core/settings_schema.h"
#include "nemerix/nemerix_messages.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gnss::nemerix {

inline constexpr std::string_view kPrefix = "PNMRX";

// Empty when `prefix` can replace "PNMRX" ('P' then 1-8 upper-case letters or digits).
std::string checkPrefix(std::string_view prefix);
// "$PNMRX110,4,35*5B" + "PXYZW" → "$PXYZW110,4,35*hh". Sentences that do not start with
// "$PNMRX" are returned unchanged; an invalid prefix returns an empty string.
std::string applyPrefix(std::string_view sentence, std::string_view prefix);
// "$" + prefix + number + body + checksum, e.g. build("110", ",4,35").
EncodeResult buildCommand(std::string_view number, std::string_view fields,
                          std::string_view prefix);
// Empty when `text` can stand as one field (no ',', '*', '$', '!' or control character), else
// the refusal naming `name`.
Refusal checkFieldText(std::string_view name, std::string_view text);

// PNMRX100: protocol 0 NMEA / 1 binary; baud 1200..57600 from the table; parity 0/1/2.
EncodeResult encodeSerialPort(int protocol, int baud, int parity,
                              std::string_view prefix = kPrefix);

// PNMRX101: every field optional; x, y, z all or none. Fields up to the last one given are
// written, followed by a trailing comma, as in the spec's examples.
struct NavInitParams {
    std::optional<std::int64_t> x, y, z; // ECEF metres, |v| <= 9999999
    std::optional<int> clockOffset;      // Hz x 100, |v| <= 999999
    std::optional<int> timeOfWeek;       // 0..604799 s
    std::optional<int> week;             // 0..9999
    std::optional<int> channels;         // 12..16
};
EncodeResult encodeNavInit(const NavInitParams &p, std::string_view prefix = kPrefix);

// PNMRX104: latitude/longitude in signed degrees (written ddmm.mmmm,N), altitude in metres.
struct LlaInitParams {
    std::optional<double> lat, lon;
    std::optional<int> altitude; // -99999..999999 m
    std::optional<int> clockOffset, timeOfWeek, week, channels;
};
EncodeResult encodeLlaInit(const LlaInitParams &p, std::string_view prefix = kPrefix);

struct RateItem {
    std::string id; // PNMRX103: GGA GLL GSA GSV RMC VTG ZDA ALL; PNMRX107: 300..304 ALL
    int value = 0;  // PNMRX103: 0..9 s (0 = off); PNMRX107: 0..3
};
// PNMRX103: output rate per NMEA message ("$PNMRX103,GSV,2,GGA,1,ZDA,0*04").
EncodeResult encodeNmeaRates(std::span<const RateItem> items, std::string_view prefix = kPrefix);
// PNMRX107: Nemerix message modes (0 off, 1 now, 2 on change, 3 now and on change).
EncodeResult encodeNemerixRates(std::span<const RateItem> items, std::string_view prefix = kPrefix);
// PNMRX108: output sequence (each of GGA GLL GSA GSV RMC VTG ZDA at most once).
EncodeResult encodeNmeaSequence(std::span<const std::string> ids,
                                std::string_view prefix = kPrefix);

// PNMRX106: internal datum 0..218 ("$PNMRX106,1,216,") or user datum 500 with dx, dy, dz
// (-9999..9999 m), inverse flattening (296..302) and semi-major axis (6376000..6379000 m).
struct DatumParams {
    int correction = 0; // 1 = apply EGM96 geoid correction
    int datum = 216;
    std::optional<int> dx, dy, dz;
    std::optional<double> inverseFlattening, semiMajorAxis;
};
EncodeResult encodeDatum(const DatumParams &p, std::string_view prefix = kPrefix);

// PNMRX110: mask id and value as text; each value checked against the mask's range
// (0: "h:m" -13..13 h; 1-3: DOP 0..10; 4: 20..45 dB-Hz; 5: 0..90 deg; 6: 400..1000;
// 7: 1/2/4; 8: 0..999999 m; 9: 0/1; 10: 0..999999 m). DOPs are given as DOP (written x10).
struct FixMaskItem {
    int id = 0;
    std::string value;
};
EncodeResult encodeFixSettings(std::span<const FixMaskItem> masks,
                               std::string_view prefix = kPrefix);

// PNMRX111: no argument (reset per the configured fix procedure), a bit field 0..255, or
// FACTORY / COLD / WARM / HOT.
EncodeResult encodeSoftwareReset(std::string_view action = {}, std::string_view prefix = kPrefix);

// PNMRX112: mode 0 fully active, 1 LDCM1 with off period 5..10 s.
EncodeResult encodePowerMode(int mode, std::optional<int> offPeriod = std::nullopt,
                             std::string_view prefix = kPrefix);

// PNMRX300 (upload, and the receiver's output): one satellite's almanac from raw (already
// scaled) field values; Almanac::setValue makes them from engineering units.
EncodeResult encodeAlmanac(const Almanac &a, std::string_view prefix = kPrefix);

// Field-less commands.
EncodeResult encodeStopCore(std::string_view prefix = kPrefix);      // PNMRX113
EncodeResult encodeVersionQuery(std::string_view prefix = kPrefix);  // PNMRX600
EncodeResult encodeIspMode(std::string_view prefix = kPrefix);       // PNMRX601
EncodeResult encodeSettingsQuery(std::string_view prefix = kPrefix); // PNMRX603

// ---- Receiver output ------------------------------------------------------------------------
// What a VT002 sends, from the message its decoder makes: encode(decode(line)) == line for a line
// in the receiver's form (hex words in their fields' widths). A value its field cannot carry is
// refused, building nothing. The simulated receiver sends only what these build.

// PNMRX301: one ephemeris subframe message (nemerix_ephemeris.cpp).
EncodeResult encodeEphemerisSubframe(const EphemerisSubframe &m, std::string_view prefix = kPrefix);
// PNMRX302, PNMRX303, PNMRX304 (nemerix_iono_utc.cpp). The SV id may be absent (302: the 8-field
// form; 303: an empty field); 303's last two words may be absent.
EncodeResult encodeIonosphere(const Ionosphere &m, std::string_view prefix = kPrefix);
EncodeResult encodeUtc(const UtcParameters &m, std::string_view prefix = kPrefix);
EncodeResult encodeHealth(const ConstellationHealth &m, std::string_view prefix = kPrefix);
// PNMRX600 / PNMRX602 (by the message's type): the report's fields as given (nemerix_version.cpp).
EncodeResult encodeVersionReport(const VersionReport &m, std::string_view prefix = kPrefix);
// PNMRX603: one settings report message, 0..4 (nemerix_settings_report.cpp).
EncodeResult encodeSettingsReport(const SettingsReport &m, std::string_view prefix = kPrefix);

// The two words of PNMRX603 message 0. The spec names them but gives no bits; the layout here is
// this program's (so nothing reads them back as settings):
//   NMRX Message Enabled: the PNMRX107 mode (0..3) of 300..304 in bits 0-1, 2-3, ... 8-9;
//   Uart Settings: the baud in bits 0-19, parity in bits 20-23, protocol in bits 24-31
//   (9600 baud, no parity, NMEA: 00002580).
std::uint64_t nmrxEnabledWord(std::span<const int, 5> modes);
std::uint64_t uartSettingsWord(int baud, int parity, int protocol);

// What PNMRX603 reports besides the settings of the schema: the receiver's own state.
struct SettingsReportState {
    std::array<std::optional<std::int64_t>, 8> iono{}; // message 1: PNMRX302's raw coefficients
    bool ionoValid = false;                            // message 1: collected from the sky
    std::uint64_t numBlocks = 0;                       // message 1: 20-year blocks since 1980
    std::uint64_t invalidSv = 0;                       // message 2: bit n-1 = SV n excluded
    int maxSvForFix = 0;                               // message 2
    std::int64_t acqThreshold1 = 0, acqThreshold2 = 0; // message 3
    std::uint64_t kalmanMode = 0;                      // message 3
};
// The five PNMRX603 messages (0..4) that report `values` (schema key → value, every readable
// setting and the rates, modes, sequence and port that message 0 carries) with `state`: what
// extractSettings reads back from them is `values` (nemerix_settings_values.cpp). Refused when
// a value the report needs is missing or not a number.
EncodeResult encodeSettingsReports(std::span<const KeyValue> values,
                                   const SettingsReportState &state,
                                   std::string_view prefix = kPrefix);

} // namespace gnss::nemerix
