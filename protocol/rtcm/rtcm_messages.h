#pragma once
// Decoded RTCM 3 messages: one struct per family, std::optional for what a message may not carry,
// and an error text instead of exceptions. decodeMessage() accepts any payload (empty, truncated,
// random) and always returns; a message it cannot read whole keeps its number and length, the
// station id when it got that far, and says why in `error`.
#include "core/wgs84.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace gnss::rtcm {

enum class System : std::uint8_t { Gps, Glonass, Galileo, Sbas, Qzss, BeiDou, NavIC };

// "GPS", "GLONASS", "Galileo", "SBAS", "QZSS", "BeiDou", "NavIC" (as the NMEA side names them).
std::string_view systemName(System s);

// 1005 (stationary RTK reference station ARP) and 1006 (the same with antenna height).
struct StationArp {
    unsigned station = 0;                    // DF003
    unsigned itrfYear = 0;                   // DF021, realisation year field (0..63)
    bool gps = false;                        // DF022
    bool glonass = false;                    // DF023
    bool galileo = false;                    // DF024
    bool nonPhysical = false;                // DF141: 1 = non-physical (computed) station
    bool singleReceiverOscillator = false;   // DF142
    unsigned quarterCycle = 0;               // DF364
    double x = 0, y = 0, z = 0;              // DF025-027, antenna reference point ECEF, metres
    std::optional<double> antennaHeight;     // DF028, metres (1006 only)
    std::optional<wgs84::Geodetic> position; // the ARP on WGS-84 (none for a point near the centre)
};

// 1007 (antenna descriptor), 1008 (+ antenna serial number), 1033 (+ receiver).
struct AntennaInfo {
    unsigned station = 0;                      // DF003
    std::string antennaDescriptor;             // DF030
    unsigned setupId = 0;                      // DF031
    std::optional<std::string> antennaSerial;  // DF033 (1008, 1033)
    std::optional<std::string> receiverType;   // DF228 (1033)
    std::optional<std::string> firmware;       // DF230 (1033)
    std::optional<std::string> receiverSerial; // DF232 (1033)
};

// Header of a Multiple Signal Message (MSM1..MSM7 of every system). The body (satellite and
// signal data) is checked for length, not decoded.
struct MsmHeader {
    System system = System::Gps;
    unsigned msmType = 0; // 1..7, the last digit of the message number
    unsigned station = 0; // DF003
    // Epoch time: GPS/Galileo/QZSS/SBAS/NavIC TOW in ms (DF004 and kin), BeiDou BDT TOW in ms
    // (DF427); GLONASS time of day in ms (DF034) with the day of week apart (DF416).
    std::uint32_t epochMs = 0;
    std::optional<unsigned> gloDayOfWeek;
    bool multipleMessage = false;    // DF393: more MSMs of this epoch follow
    unsigned iods = 0;               // DF409
    unsigned clockSteering = 0;      // DF411
    unsigned externalClock = 0;      // DF412
    bool smoothing = false;          // DF417 divergence-free smoothing
    unsigned smoothingInterval = 0;  // DF418 (coded)
    std::uint64_t satelliteMask = 0; // DF394, bit 63 = satellite 1
    std::uint32_t signalMask = 0;    // DF395, bit 31 = signal 1
    std::uint64_t cellMask = 0;      // DF396, right-aligned: nsat × nsig bits, first cell highest
    std::array<std::uint8_t, 64> satellites{}; // satellite ids (1..64) from the mask, ascending
    std::array<std::uint8_t, 32> signalList{}; // signal ids (1..32) from the mask, ascending
    std::uint8_t satelliteCount = 0;
    std::uint8_t signalCount = 0;
    std::uint8_t cellCount = 0; // cells present (bits set in the cell mask)

    std::span<const std::uint8_t> satelliteIds() const {
        return {satellites.data(), satelliteCount};
    }
    std::span<const std::uint8_t> signalIds() const { return {signalList.data(), signalCount}; }
};

// Broadcast ephemerides: 1019 GPS, 1020 GLONASS, 1042 BeiDou, 1044 QZSS, 1045 Galileo F/NAV,
// 1046 Galileo I/NAV. Only what tells which satellite and which issue this is.
struct Ephemeris {
    System system = System::Gps;
    unsigned satellite = 0;       // the satellite id field as sent (QZSS: 1..10)
    unsigned prn = 0;             // PRN or slot (QZSS: 192 + id)
    std::optional<unsigned> week; // as broadcast: GPS/QZSS 10 bits, Galileo 12, BeiDou 13
    std::optional<unsigned> iode; // GPS/QZSS IODE, Galileo IODnav, BeiDou AODE
    std::optional<unsigned> iodc; // GPS/QZSS IODC, BeiDou AODC
    std::optional<std::uint32_t> tocSeconds;
    std::optional<std::uint32_t> toeSeconds;
    std::optional<unsigned> health; // GPS/QZSS SV health (6 bits), BeiDou SatH1, GLONASS Bn MSB
    // GLONASS only
    std::optional<int> frequencyChannel;    // DF040 − 7: −7..+6 (and beyond for bad data)
    std::optional<std::uint32_t> tkSeconds; // DF107: frame start time within the day
    std::optional<unsigned> tbMinutes;      // DF110 × 15: ephemeris reference time within the day
    // Galileo only: signal health status and data validity (F/NAV: E5a; I/NAV: E5b and E1-B)
    std::optional<unsigned> e5aHealth, e5aValidity, e5bHealth, e5bValidity, e1bHealth, e1bValidity;
};

// 1230 GLONASS L1/L2 code-phase biases, in the order of the FDMA signals mask (DF422).
struct GlonassBiases {
    static constexpr std::array<std::string_view, 4> kSignals = {"1C", "1P", "2C", "2P"};
    unsigned station = 0;
    bool aligned = false; // DF421 code-phase bias indicator: 1 = phase observations aligned
    unsigned mask = 0;    // DF422, 4 bits: L1 C/A, L1 P, L2 C/A, L2 P (MSB first)
    std::array<bool, 4> present{};                 // per signal: in the mask
    std::array<std::optional<double>, 4> biases{}; // DF423-426, metres; none when not valid
};

// Legacy RTK observables: 1001-1004 GPS (L1; L1 extended; L1/L2; L1/L2 extended) and
// 1009-1012 GLONASS (the same four). One signal per band; distances in metres.
struct LegacySignal {
    unsigned code = 0; // code indicator: DF010/DF016 (GPS), DF039/DF046 (GLONASS)
    // L1: DF011 × 0.02 (+ DF014 × 299792.458 GPS, DF041/DF044 × 599584.916 GLONASS); modulo one
    // light-ms (two for GLONASS) without the ambiguity (1001, 1003, 1009, 1011).
    // L2: L1 + DF017/DF047 × 0.02; none when sent as invalid (−8192).
    std::optional<double> pseudorange;
    // L1 pseudorange + DF012/DF042 (L1) or DF018/DF048 (L2) × 0.0005; none when −524288 (invalid).
    std::optional<double> phaseRange;
    unsigned lockTime = 0;     // lock time indicator: DF013/DF019 (GPS), DF043/DF049 (GLONASS)
    std::optional<double> cnr; // dB-Hz, DF015/DF020/DF045/DF050 × 0.25 (extended only; 0 = none)
};

struct LegacySatellite {
    unsigned id = 0;                     // DF009 GPS PRN, DF038 GLONASS slot
    std::optional<int> frequencyChannel; // GLONASS: DF040 − 7
    std::optional<unsigned> ambiguity;   // DF014 / DF044 (extended messages), light-ms / 2 ms
    LegacySignal l1;
    std::optional<LegacySignal> l2; // 1003, 1004, 1011, 1012
};

struct LegacyObservables {
    unsigned number = 1001;         // DF002: which of the eight
    unsigned station = 0;           // DF003
    std::uint32_t epochMs = 0;      // DF004 GPS time of week, DF034 GLONASS time of day (ms)
    bool synchronous = false;       // DF005: more observables of this epoch follow
    bool smoothing = false;         // DF007 / DF036 divergence-free smoothing
    unsigned smoothingInterval = 0; // DF008 / DF037 (coded)
    std::vector<LegacySatellite> satellites; // DF006 / DF035 of them (at most 31)

    // The last two bits of the offset from 1001 / 1009: bit 1 = L2 too, bit 0 = extended.
    System system() const { return number >= 1009 ? System::Glonass : System::Gps; }
    unsigned kind() const { return (number - (number >= 1009 ? 1009 : 1001)) & 3; }
    bool hasL2() const { return kind() >= 2; }
    bool extended() const { return kind() % 2 == 1; }
};

struct RtcmMessage {
    unsigned number = 0;    // DF002; 0 when the payload is too short to hold one
    std::size_t length = 0; // payload bytes
    std::optional<unsigned> station;
    std::variant<std::monostate, StationArp, AntennaInfo, MsmHeader, Ephemeris, GlonassBiases,
                 LegacyObservables>
            body;
    std::string_view error; // why the body is missing (static text); empty when decoded or
                            // when the message is simply not one this decoder reads
};

// Decodes one frame's payload (without header and CRC). Never throws.
RtcmMessage decodeMessage(std::span<const std::uint8_t> payload);

// Is `number` an MSM (1071..1077, 1081..1087, ..., 1131..1137)? Then system and type.
bool isMsm(unsigned number);
// RINEX observation code of an MSM signal id ("1C", "2L"...), empty when unknown.
std::string_view msmSignalName(System system, unsigned signalId);
// PRN of an MSM satellite id: SBAS 119 + id, QZSS 192 + id, the id itself otherwise.
unsigned msmPrn(System system, unsigned satelliteId);
// Satellite and signal data bits of an MSM body; the payload must hold header + this.
std::size_t msmBodyBits(unsigned msmType, unsigned satellites, unsigned cells);
inline constexpr std::size_t kMsmHeaderBits = 169; // before the cell mask

// Is `number` a legacy observables message (1001-1004, 1009-1012)?
bool isLegacyObservables(unsigned number);
// RINEX observation code of a legacy signal: band 1 or 2 and its code indicator ("1C", "2P"...).
std::string_view legacySignalName(System system, unsigned band, unsigned code);
// Header and per-satellite bits of a legacy observables message (0 for other numbers).
std::size_t legacyHeaderBits(unsigned number);
std::size_t legacySatelliteBits(unsigned number);

} // namespace gnss::rtcm
