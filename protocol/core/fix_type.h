#pragma once
// Fix type, as one badge everywhere: the same words and colours in the status bar, the fix dock,
// charts and the deviation plot. Vendors' extra GGA qualities map onto these.
#include <cstdint>
#include <string_view>

namespace gnss {

enum class FixType : std::uint8_t {
    None,
    Estimated, // dead reckoning
    Fix2D,
    Fix3D,
    Dgnss, // DGPS / SBAS
    RtkFloat,
    RtkFixed,
    Manual, // fixed / manually entered position
    Simulator,
};

std::string_view toString(FixType f); // "none", "estimated", "2d", "3d", "dgnss", ...

// Standard NMEA GGA quality (0-8) → fix type (before GSA refines 2D/3D).
FixType fixTypeFromGgaQuality(int quality);
// RMC/GNS/GLL/VTG mode indicator (A D E F M N P R S) → fix type; None for unknown letters.
FixType fixTypeFromModeIndicator(char mode);

} // namespace gnss
