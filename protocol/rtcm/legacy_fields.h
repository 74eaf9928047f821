#pragma once
// Resolutions and markers of the legacy observables' fields (1001-1004, 1009-1012), shared by
// legacy_observables.cpp (decoding) and legacy_encoder.cpp. Internal to gnss_rtcm.
#include <cstdint>

namespace gnss::rtcm::legacy {

// Metres of one ambiguity step: a light-millisecond (GPS DF014), two (GLONASS DF044).
inline constexpr double kGpsAmbiguity = 299792.458;
inline constexpr double kGlonassAmbiguity = 599584.916;
// Pseudoranges and the L2−L1 pseudorange difference (DF011, DF017, DF041, DF047).
inline constexpr double kRangeStep = 0.02;
// Phase range − L1 pseudorange (DF012, DF018, DF042, DF048).
inline constexpr double kPhaseStep = 0.0005;
inline constexpr double kCnrStep = 0.25; // DF015, DF020, DF045, DF050; 0 = not computed
inline constexpr std::int64_t kInvalidPhase = -524288; // 0x80000 in 20 bits
inline constexpr std::int64_t kInvalidL2Range = -8192; // 0x2000 in 14 bits

// Widths that differ between GPS and GLONASS.
struct Widths {
    unsigned range = 24;    // DF011 24, DF041 25
    unsigned ambiguity = 8; // DF014 8, DF044 7
    unsigned channel = 0;   // DF040 5 (GLONASS only)
    double ambiguityMetres = kGpsAmbiguity;
};
inline constexpr Widths kGpsWidths{};
inline constexpr Widths kGlonassWidths{25, 7, 5, kGlonassAmbiguity};

} // namespace gnss::rtcm::legacy
