#pragma once
// Typed encoders for every NVS input sentence. The command queue, the simulator, the settings
// forms and `gnss-cli encode` all build commands here. Each validates every value against the
// spec's range first (the settings schema rows where one exists) and builds nothing on error:
// EncodeResult.error then names the parameter and the accepted range.
#include "core/settings_schema.h"
#include "nvs_messages.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gnss::nvs {

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

// Table 4: every PNVGRTK parameter name, in the spec's order (33 names).
std::span<const std::string_view> rtkParameterNames();
bool isRtkParameter(std::string_view name);

// Validation of one PNVGRTK value against Table 4 (empty string when valid).
Refusal validateRtkValue(std::string_view name, std::string_view value);

} // namespace gnss::nvs
