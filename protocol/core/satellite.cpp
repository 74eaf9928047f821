#include "core/satellite.h"

#include <array>
#include <cstdio>

namespace gnss {

std::string_view toString(Constellation c) {
    switch (c) {
    case Constellation::Gps: return "GPS";
    case Constellation::Glonass: return "GLONASS";
    case Constellation::Galileo: return "Galileo";
    case Constellation::BeiDou: return "BeiDou";
    case Constellation::Qzss: return "QZSS";
    case Constellation::Sbas: return "SBAS";
    case Constellation::NavIC: return "NavIC";
    case Constellation::Unknown: break;
    }
    return "unknown";
}

char rinexLetter(Constellation c) {
    switch (c) {
    case Constellation::Gps: return 'G';
    case Constellation::Glonass: return 'R';
    case Constellation::Galileo: return 'E';
    case Constellation::BeiDou: return 'C';
    case Constellation::Qzss: return 'J';
    case Constellation::Sbas: return 'S';
    case Constellation::NavIC: return 'I';
    case Constellation::Unknown: break;
    }
    return '?';
}

Constellation constellationOfTalker(std::string_view t) {
    if (t.size() != 2) return Constellation::Unknown;
    // Every GSV asks: the G talkers by a table of their second letter (no chain of comparisons,
    // no jump table, nothing for a branch predictor to miss).
    static constexpr auto kG = [] {
        std::array<Constellation, 26> g{};
        g.fill(Constellation::Unknown); // GN (combined) and anything else
        g['P' - 'A'] = Constellation::Gps;
        g['L' - 'A'] = Constellation::Glonass;
        g['A' - 'A'] = Constellation::Galileo;
        g['B' - 'A'] = Constellation::BeiDou;
        g['Q' - 'A'] = Constellation::Qzss;
        g['I' - 'A'] = Constellation::NavIC;
        return g;
    }();
    const auto second = static_cast<unsigned>(static_cast<unsigned char>(t[1]) - 'A');
    if (t[0] == 'G') return second < kG.size() ? kG[second] : Constellation::Unknown;
    if (t == "BD") return Constellation::BeiDou;
    if (t == "QZ") return Constellation::Qzss;
    return Constellation::Unknown;
}

Constellation constellationOfSystemId(int id) {
    switch (id) {
    case 1: return Constellation::Gps;
    case 2: return Constellation::Glonass;
    case 3: return Constellation::Galileo;
    case 4: return Constellation::BeiDou;
    case 5: return Constellation::Qzss;
    case 6: return Constellation::NavIC;
    case 15: return Constellation::Qzss; // GeoStar GeoS-5 (section 3.4)
    default: return Constellation::Unknown;
    }
}

namespace {

// The 2.x "extended" numbering shared by GP and GN talkers.
SatelliteRef byRange(int id) {
    if (id >= 1 && id <= 32) return {Constellation::Gps, id};
    if (id >= 33 && id <= 64) return {Constellation::Sbas, id + 87};
    if (id >= 65 && id <= 96) return {Constellation::Glonass, id - 64};
    if (id >= 120 && id <= 158) return {Constellation::Sbas, id};
    if (id >= 193 && id <= 199) return {Constellation::Qzss, id - 192};
    if (id >= 201 && id <= 263) return {Constellation::BeiDou, id - 200};
    if (id >= 301 && id <= 336) return {Constellation::Galileo, id - 300};
    if (id >= 401 && id <= 463) return {Constellation::BeiDou, id - 400};
    return {Constellation::Unknown, id};
}

} // namespace

SatelliteRef mapSatelliteId(Constellation system, int id) {
    switch (system) {
    case Constellation::Gps:
        // GP talker: GPS proper, but receivers put SBAS (and in 2.x everything) here too.
        return byRange(id);
    case Constellation::Glonass:
        if (id >= 65 && id <= 96) return {Constellation::Glonass, id - 64};
        if (id >= 1 && id <= 32) return {Constellation::Glonass, id};
        return byRange(id);
    case Constellation::Galileo:
        if (id >= 1 && id <= 36) return {Constellation::Galileo, id};
        if (id >= 101 && id <= 136) return {Constellation::Galileo, id - 100};
        if (id >= 301 && id <= 336) return {Constellation::Galileo, id - 300};
        return {Constellation::Galileo, id};
    case Constellation::BeiDou:
        if (id >= 1 && id <= 63) return {Constellation::BeiDou, id};
        if (id >= 201 && id <= 263) return {Constellation::BeiDou, id - 200};
        if (id >= 401 && id <= 463) return {Constellation::BeiDou, id - 400};
        return {Constellation::BeiDou, id};
    case Constellation::Qzss:
        if (id >= 193 && id <= 202) return {Constellation::Qzss, id - 192};
        return {Constellation::Qzss, id};
    case Constellation::NavIC: return {Constellation::NavIC, id};
    case Constellation::Sbas:
        if (id >= 33 && id <= 64) return {Constellation::Sbas, id + 87};
        return {Constellation::Sbas, id};
    case Constellation::Unknown: break;
    }
    return byRange(id);
}

std::string_view signalName(Constellation c, int s) {
    switch (c) {
    case Constellation::Gps:
    case Constellation::Sbas: {
        static constexpr std::string_view n[] = {"",      "L1 C/A", "L1 P(Y)", "L1 M", "L2 P(Y)",
                                                 "L2C-M", "L2C-L",  "L5-I",    "L5-Q"};
        return s >= 0 && s < 9 ? n[s] : std::string_view{};
    }
    case Constellation::Glonass: {
        static constexpr std::string_view n[] = {"", "G1 C/A", "G1 P", "G2 C/A", "G2 P"};
        return s >= 0 && s < 5 ? n[s] : std::string_view{};
    }
    case Constellation::Galileo: {
        static constexpr std::string_view n[] = {"",     "E5a",   "E5b",  "E5a+b",
                                                 "E6-A", "E6-BC", "E1-A", "E1-BC"};
        return s >= 0 && s < 8 ? n[s] : std::string_view{};
    }
    case Constellation::BeiDou: {
        static constexpr std::string_view n[] = {"",      "B1I", "B1Q", "B1C", "B1A", "B2a", "B2b",
                                                 "B2a+b", "B3I", "B3Q", "B3A", "B2I", "B2Q"};
        return s >= 0 && s < 13 ? n[s] : std::string_view{};
    }
    case Constellation::Qzss: {
        static constexpr std::string_view n[] = {"",     "L1 C/A", "L1C(D)", "L1C(P)",
                                                 "LIS",  "L2C-M",  "L2C-L",  "L5-I",
                                                 "L5-Q", "L6D",    "L6E"};
        return s >= 0 && s < 11 ? n[s] : std::string_view{};
    }
    case Constellation::NavIC: {
        static constexpr std::string_view n[] = {"", "L5-SPS", "S-SPS", "L5-RS", "S-RS", "L1-SPS"};
        return s >= 0 && s < 6 ? n[s] : std::string_view{};
    }
    case Constellation::Unknown: break;
    }
    return {};
}

std::string satelliteLabel(SatelliteRef s) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%c%02d", rinexLetter(s.system), s.prn);
    return buf;
}

} // namespace gnss
