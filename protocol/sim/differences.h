#pragma once
// Differences: what a simulated receiver reports otherwise than the sky's truth, on purpose, so
// that a comparison of receivers can be checked against known answers (`gnss-sim --offset
// 0.3,-0.2,0.5 --cn0-offset GPS:-3,GLONASS:2 --drop G05,R12 --latency 250`): its position moved by
// a fixed east/north/up offset, its C/N0 shifted per constellation, chosen satellites never
// reported, its output sent a fixed time after the epoch it describes.
#include "core/satellite.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gnss::sim {

struct SkySnapshot;

struct Differences {
    double east = 0, north = 0, up = 0; // metres added to the reported position
    // dB added to the C/N0 of every signal of a constellation (Unknown: of every signal).
    std::vector<std::pair<Constellation, double>> cn0;
    std::vector<SatelliteRef> drop; // never reported, not used
    double latency = 0;             // seconds between an epoch and its output leaving

    bool any() const;
    double cn0Offset(Constellation c) const;
};

// "E,N,U" in metres.
std::optional<Differences> parseOffset(std::string_view text, Differences d, std::string &error);
// "DB" for every constellation, or "SYS:DB[,SYS:DB]" (GPS, GLONASS, Galileo, BeiDou, QZSS, SBAS
// or their letters G R E C J S).
std::optional<Differences> parseCn0Offset(std::string_view text, Differences d, std::string &error);
// "G05,R12,E31,C07": RINEX-style satellite labels.
std::optional<Differences> parseDrop(std::string_view text, Differences d, std::string &error);

// The snapshot as the receiver reports it: position moved, C/N0 shifted (never below 0), the
// dropped satellites gone (and no longer counted as used).
void applyDifferences(const Differences &d, SkySnapshot &snap);

} // namespace gnss::sim
