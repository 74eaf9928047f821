#pragma once
// Typed encoders for every NVS sentence: the commands (input sentences) the command queue, the
// simulator, the settings forms and `gnss-cli encode` build, and the sentences the receiver
// sends, which the simulated receiver builds from the structs the decoders fill
// (encode(decode(line)) == line in the receiver's layout). Each validates every value against
// the spec's range first (the settings schema rows where one exists) and builds nothing on
// error: EncodeResult.error then names the parameter and the accepted range.
#include "core/settings_schema.h"
#include "nvs/nvs_messages.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gnss::nvs {

// 4.5: at most 20 messages in a port's output list; 4.15: at most 32 known base stations, ids
// 0-4095.
inline constexpr std::size_t kMaxOutputMessages = 20;
inline constexpr std::size_t kMaxStations = 32;
inline constexpr int kMaxStationId = 4095;
// 4.6: the RTCM data age PNVGBSS reports, "supported values: 0-999.9 seconds".
inline constexpr double kMaxRtcmAge = 999.9;

// ---- Commands ---------------------------------------------------------------------------------

// 3.8 Q: "$<requester>GPQ,<address>" — `$GPGPQ,PNVGTST*21`. The requester talker is any two
// upper-case letters/digits; the address is 3 characters (standard) or 7 (proprietary).
EncodeResult encodeQuery(std::string_view requesterTalker, std::string_view address);
// 4.1 "$PNVGVER*4E".
EncodeResult encodeVersionRequest();
// 4.2 PNVGNME: time decimals 0..6, position decimals 0..9, talker mode 0/1 (optional field).
EncodeResult encodeNme(int timeDecimals, int positionDecimals,
                       std::optional<int> talkerMode = std::nullopt);
// 4.3 PNVGRST: 'F' cold start, 'W' warm restart (user settings kept either way).
EncodeResult encodeRst(char type);
// 4.4 PNVGRZA: port 0..3 (0 current), baud 4800..460800, protocol 0/1/7.
EncodeResult encodeRza(int port, int baud, int protocol);
// 4.5 PNVGRZB: no entries = clear the list ("$PNVGRZB*45", "$PNVGRZB,PORT,2*6E"); entries add
// messages with rates. port nullopt = the current port.
EncodeResult encodeRzb(std::optional<int> port, std::span<const RzbEntry> entries);
// 4.8 PNVGCFG: 'W' save to flash, 'E' erase (defaults), 'R' erase and restart.
EncodeResult encodeCfg(char action);
// 4.9 PNVGPPS: fields left nullopt are sent empty and stay unchanged. All empty = read back.
struct PpsSettings {
    std::optional<char> type;      // P, A
    std::optional<char> mode;      // I, S
    std::optional<char> reference; // U, S, G, N
    std::optional<int> adjust;     // 0, 1
    std::optional<int> duration;   // 1..1000 microseconds
    std::optional<char> validity;  // E, D
    std::optional<int> cableDelay; // 0..9999 nanoseconds
};
EncodeResult encodePps(const PpsSettings &pps);
// 4.14 PNVGRTK: `set` parameters are sent with their values (several values separated by ','
// in one string: BASEXYZ "x,y,z"; BASEBLH "B,L,H" in radians/metres or the NMEA form
// "ddmm.mmmm,N,dddmm.mmmm,E,H"), `query` parameters without. Names are Table 4's.
struct RtkSet {
    std::string name;
    std::string value;
};
EncodeResult encodeRtk(std::span<const RtkSet> set, std::span<const std::string> query = {});
// 4.15 PNVGIDL subcommands. ADD takes 0, 1 or 2 values (station id 0..4095, ICB -1..1 cycle);
// an ICB without a station id is refused (the spec's field order does not allow it).
EncodeResult encodeIdlMode(int mode);
EncodeResult encodeIdlAdd(std::optional<int> stationId = std::nullopt,
                          std::optional<double> icb = std::nullopt);
EncodeResult encodeIdlRemove(int stationId);
EncodeResult encodeIdlClear();
EncodeResult encodeIdlShow();

// ---- What the receiver sends --------------------------------------------------------------------
// Each takes its decoder's struct. Fields left nullopt are sent empty; times are printed with the
// decimals they carry (TimeOfDay::decimals: PNVGNME's, or as decoded); every other field has
// the receiver's own layout (the spec's examples): metres and m/s with 3 decimals, angles and
// DOPs with 2. A number that is not finite or is out of its field's range, a mode indicator
// other than A D F R E N, or text that would break the sentence is refused.

// 4.1 the reply: manufacturer, device, firmware versions as printed; a request gives "$PNVGVER".
EncodeResult encodeVer(const Ver &m);
// 4.6 PNVGBSS: RTCM counts, distance to the base (m), RTCM age (0..999.9 s; empty before any).
EncodeResult encodeBss(const Bss &m);
// 4.7 PNVGTST: the name/result pairs in order (ID a decimal number, ANT 0..2).
EncodeResult encodeTst(const Tst &m);
// 4.10 PNVGIMU; without a time, the form of firmware before 1.5 (no time field).
EncodeResult encodeImu(const Imu &m);
// 4.11 PNVGBRS, 4.12 PNVGBLS (without a time, PNVGBLS's form before 1.5).
EncodeResult encodeBrs(const Brs &m);
EncodeResult encodeBls(const Bls &m);
// 4.13 PNVGVOG.
EncodeResult encodeVog(const Vog &m);
// 4.15 PNVGIDL, any of its forms: the commands (as encodeIdlMode ... encodeIdlShow) and the
// replies: REMOVE/CLEAR with their word (status, or "OK" when `ok`), a SHOW item
// ($PNVGIDL,<count>,<index>,<id>,<icb>) and an empty list's "$PNVGIDL,0".
EncodeResult encodeIdl(const Idl &m);
// 4.16 PNVGTME (time of week with 9 decimals), 4.17 PNVGTMU.
EncodeResult encodeTme(const Tme &m);
EncodeResult encodeTmu(const Tmu &m);
// 4.18 PNVGTMC: the GGA layout, the position with `positionDecimals` (PNVGNME's, 0..9).
EncodeResult encodeTmc(const Tmc &m, int positionDecimals);
// 4.19-4.21 PNVGSDP, PNVGSDV, PNVGSDH.
EncodeResult encodeSdp(const Sdp &m);
EncodeResult encodeSdv(const Sdv &m);
EncodeResult encodeSdh(const Sdh &m);
// 4.22 PNVGDOP.
EncodeResult encodeDop(const Dop &m);

// ---- PNVGRTK's parameters -----------------------------------------------------------------------

// Table 4: every PNVGRTK parameter name, in the spec's order (33 names).
std::span<const std::string_view> rtkParameterNames();
bool isRtkParameter(std::string_view name);

// Validation of one PNVGRTK value against Table 4 (empty string when valid).
Refusal validateRtkValue(std::string_view name, std::string_view value);

} // namespace gnss::nvs
