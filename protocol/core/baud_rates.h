#pragma once
// Serial line speeds, in one place: the standard rates a port can be set to (what the baud box
// offers, what a command's speed field may name) and the order in which detection tries them
// (receivers' usual defaults first). A receiver family's own list is in its dialect record.
#include <algorithm>
#include <array>
#include <span>
#include <string>

namespace gnss {

inline constexpr std::array<int, 11> kStandardBauds = {1200,  2400,   4800,   9600,   19200, 38400,
                                                       57600, 115200, 230400, 460800, 921600};

// Detection order: 115200 (NVS, GeoStar) and 9600 (NMEA, Nemerix) first, then the rest.
inline constexpr std::array<int, 9> kDetectionBauds = {115200, 9600,   38400,  57600, 4800,
                                                       19200,  230400, 460800, 921600};

// The speed a port is opened at before anything is known.
inline constexpr int kDefaultSerialBaud = kDetectionBauds.front();

inline bool isStandardBaud(int baud) {
    return std::find(kStandardBauds.begin(), kStandardBauds.end(), baud) != kStandardBauds.end();
}

// "1200, 2400, 4800" (for an error that says what is accepted).
inline std::string baudList(std::span<const int> bauds) {
    std::string s;
    for (int b : bauds) s += (s.empty() ? "" : ", ") + std::to_string(b);
    return s;
}

} // namespace gnss
