#pragma once
// Building RTCM 3 frames: for tests now, for the receiver simulator later. Each function returns
// the whole frame (0xD3, length, payload, CRC-24Q) as bytes in a std::string, or an empty string
// when the payload would not fit a frame (over 1023 bytes). Fields out of range are cut to their
// width, as the wire would carry them.
#include "rtcm/rtcm_messages.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gnss::rtcm {

// Any payload as a frame.
std::string frame(std::span<const std::uint8_t> payload);
inline std::string frame(const std::vector<std::uint8_t> &payload) {
    return frame(std::span<const std::uint8_t>(payload));
}

// 1005, or 1006 when antennaHeight is set. position is ignored (derived on decoding).
std::string encodeStationArp(const StationArp &a);
// 1007, 1008 or 1033 (`number`); the optional strings absent are sent empty.
std::string encodeAntennaInfo(unsigned number, const AntennaInfo &a);
// An MSM of h.system and h.msmType with h's header fields and masks (satellite and signal masks;
// the cell mask's low nsat × nsig bits) and an all-zero body of the right length.
std::string encodeMsm(const MsmHeader &h);
// 1019, 1020, 1042, 1044, 1045 or 1046 (`number`): e's identifying fields, every orbit and clock
// term zero. GLONASS: satellite, frequencyChannel, tkSeconds, health, tbMinutes.
std::string encodeEphemeris(unsigned number, const Ephemeris &e);
// 1230; mask from b.present, invalid values (no bias) sent as −32768.
std::string encodeGlonassBiases(const GlonassBiases &b);
// 1001-1004 or 1009-1012 (o.number), the first 31 satellites (legacy_encoder.cpp). An extended
// message sends the satellite's ambiguity, or the whole light-ms (GLONASS: 2 ms) of its L1
// pseudorange when none; the others send the L1 pseudorange modulo that when it does not fit.
// Phase ranges and the L2 pseudorange go as differences to the L1 pseudorange sent; absent ones
// as "invalid", an absent CNR as 0, an absent L1 pseudorange as 0, absent L2 as all invalid.
std::string encodeLegacy(const LegacyObservables &o);

// The payload builders behind the frame functions (for tests that cut or corrupt payloads).
std::vector<std::uint8_t> stationArpPayload(const StationArp &a);
std::vector<std::uint8_t> antennaInfoPayload(unsigned number, const AntennaInfo &a);
std::vector<std::uint8_t> msmPayload(const MsmHeader &h);
std::vector<std::uint8_t> ephemerisPayload(unsigned number, const Ephemeris &e);
std::vector<std::uint8_t> glonassBiasesPayload(const GlonassBiases &b);
std::vector<std::uint8_t> legacyPayload(const LegacyObservables &o);

} // namespace gnss::rtcm
