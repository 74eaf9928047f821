#pragma once
// Constellations and satellite numbering.
//
// NMEA numbers satellites by talker and version (docs/spec-notes.md, NMEA 0183 4.11 table 20):
//   talker GP/GN (2.x "extended" numbering): 1-32 GPS, 33-64 SBAS (PRN = id + 87),
//   65-96 GLONASS (slot = id - 64), 120-158 SBAS PRN, 193-202 QZSS (PRN = id - 192),
//   201-263 BeiDou (PRN = id - 200, SiRF "GB"), 301-336 Galileo, 401-463 BeiDou;
//   GL 65-96 (or 1-32), GA 1-36 (or 101-136 / 301-336), GB/BD 1-63 (or 201-263),
//   GQ/QZ 1-10 (or 193-202), GI 1-14.
//   NMEA 4.10+ GSA carries a GNSS system id (1 GPS, 2 GLONASS, 3 Galileo, 4 BeiDou, 5 QZSS,
//   6 NavIC; GeoStar prints 15 for QZSS), and GSV a signal id.
// A dialect may override the mapping where its receiver numbers differently (GeoStar v2.x prints
// Galileo as 101-136 under the GP talker).
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace gnss {

enum class Constellation : std::uint8_t {
    Unknown,
    Gps,
    Glonass,
    Galileo,
    BeiDou,
    Qzss,
    Sbas,
    NavIC
};

std::string_view toString(Constellation c); // "GPS", "GLONASS", ... as gnss-cli prints them
char rinexLetter(Constellation c);          // G R E C J S I, '?' for unknown

struct SatelliteRef {
    Constellation system = Constellation::Unknown;
    int prn = 0; // PRN, or GLONASS slot
    bool operator==(const SatelliteRef &) const = default;
};

// Constellation named by a talker id ("GP" → GPS). GN and unknown talkers → Unknown.
Constellation constellationOfTalker(std::string_view talker);
// NMEA 4.10+ GNSS system id (GSA last field) → constellation.
Constellation constellationOfSystemId(int systemId);

// Maps an NMEA satellite id to (constellation, PRN/slot). `system` is the constellation known
// from context (talker or system id), or Unknown to infer it from the id's range.
SatelliteRef mapSatelliteId(Constellation system, int id);

// mapSatelliteId, with the numbering each constellation's own talker uses (GPS 1-32, GLONASS
// 65-96, Galileo 1-36, BeiDou 1-63, QZSS 193-202, SBAS 33-64, NavIC any) answered inline from a
// table: every satellite of every GSV and GSA is mapped, and the call and the switch behind it
// were a few per cent of a full decode.
inline SatelliteRef mapSatelliteIdInline(Constellation system, int id) {
    struct Range {
        int first, last, offset; // ids first..last are PRN id - offset
    };
    static constexpr Range kOwn[] = {
            {1, 0, 0},                        // Unknown: by the id's range (mapSatelliteId)
            {1, 32, 0},                       // Gps
            {65, 96, 64},                     // Glonass
            {1, 36, 0},                       // Galileo
            {1, 63, 0},                       // BeiDou
            {193, 202, 192},                  // Qzss
            {33, 64, -87},                    // Sbas
            {-2147483647 - 1, 2147483647, 0}, // NavIC
    };
    const auto k = static_cast<std::size_t>(system);
    if (k < std::size(kOwn) && id >= kOwn[k].first && id <= kOwn[k].last)
        return {system, id - kOwn[k].offset};
    return mapSatelliteId(system, id);
}

// Human name of a signal id (NMEA 4.11 table 21) for a constellation: "L1 C/A", "E5a", ...
// Empty for signal 0 ("all signals") or an unknown id.
std::string_view signalName(Constellation c, int signalId);

// "G05", "R12", "E31" (RINEX style, two digits).
std::string satelliteLabel(SatelliteRef s);

} // namespace gnss
