#pragma once
// The three 32-bit words of the RQUERY reply (GeoS-5 NMEA protocol v4.0, section 3.11), decoded
// bit by bit into named, typed fields:
//   table 7: receiver status word, table 8: configuration register #1,
//   table 9: configuration register #2.
// Plain functions of the word, so the decoder, the status view and the simulator share them;
// each word is also built back from its fields (encode, the inverse of decode, bit by bit), so a
// receiver that reports its state (the simulator) never places a bit itself.
#include "core/json_writer.h"
#include "core/refusal.h"

#include <cstdint>
#include <string_view>

namespace gnss::geostar {

// A word built from its fields, or why it cannot be (a field wider than its bits).
struct EncodedWord {
    std::uint32_t word = 0;
    Refusal refusal; // empty when built
    bool ok() const { return refusal.empty(); }
};

// Table 7, bits 7:6.
enum class AntennaState : std::uint8_t {
    NotMeasured = 0,
    Overloaded = 1,
    Disconnected = 2,
    Ok = 3
};
std::string_view toString(AntennaState a); // "not_measured", "overloaded", "disconnected", "ok"

// Table 7: receiver status word.
struct StatusWord {
    std::uint32_t raw = 0;
    bool jammingDetected = false;          // 31
    bool flashWriteInProgress = false;     // 30
    bool geoPathActive = false;            // 28 (GeoS-5MP only)
    bool referenceWithinThreshold = false; // 27: computed vs reference coordinates within
                                           // threshold (fixed-coordinates mode only)
    bool averagingInProgress = false;      // 26
    bool rtcmCorrectionsUsed = false;      // 25
    bool sbasCorrectionsUsed = false;      // 24
    bool active = false;                   // 23: 1 ACTIVE, 0 SLEEP
    bool differential = false;             // 22: solution type 0 autonomous, 1 differential
    bool extrapolated = false;             // 21
    bool stationary = false;               // 20: static navigation (stopped)
    bool solutionAvailable = false;        // 19
    bool validSinceStart = false;          // 18: at least one valid solution since start
    bool solution2D = false;               // 16: 0 3D, 1 2D
    bool clockRestoredHotStart = false;    // 15: time scale restored in hot start
    bool gpsIonoUtcAvailable = false;      // 14
    bool dateFromNavMessage = false;       // 13
    bool timeFromNavMessage = false;       // 12
    bool qzssAlmanac = false;              // 11
    bool galileoAlmanac = false;           // 10
    bool glonassAlmanac = false;           // 9
    bool gpsAlmanac = false;               // 8
    AntennaState antenna = AntennaState::NotMeasured; // 7:6
    bool glonassAgcOk = false;                        // 5
    bool gpsAgcOk = false;                            // 4
    bool settingsLoadedFromFlash = false;             // 3
    bool pllOk = false;                               // 2
    bool rtcOk = false;                               // 1
    bool backupRamOk = false;                         // 0
    static constexpr std::uint32_t kReservedMask = (1u << 29) | (1u << 17);

    static StatusWord decode(std::uint32_t word);
    // The word from the fields above; the reserved bits are taken from `raw` (a decoded word
    // keeps them, so encode(decode(w)) == w; a word filled in field by field has none).
    EncodedWord encode() const;
    void writeJson(JsonWriter &w) const;
};

// Table 8, bits 23:21.
enum class DynamicsProfile : std::uint8_t { Auto, PedestrianCar, Marine, Airborne, HighDynamics };
// Table 8, bits 11:9.
enum class PpsTimeScale : std::uint8_t { Gps, Utc, Glonass, UtcSu, Reserved };

// Table 8: receiver configuration register #1.
struct ConfigRegister1 {
    std::uint32_t raw = 0;
    bool antennaPower = false;         // 30
    bool fixedCoordinatesMode = false; // 28: 0 autonomous/differential, 1 fixed coordinates
    bool raim = false;                 // 27 (T-RAIM)
    bool smoothedPseudoranges = false; // 26: in binary message 0x10
    bool fixByRequest = false;         // 25: power saving type 0 RELAXED FIX, 1 FIX-BY-REQUEST
    bool powerSavingEnabled = false;   // 24
    int dynamicsCode = 0;              // 23:21 (0 auto, 1 pedestrian/car, 2 marine, 3 airborne,
                                       //        4 high dynamics (GeoS-5MH); 5-7 undefined)
    int rateCode = 0;                  // 19:18 (0 10 Hz, 1 5 Hz, 2 2 Hz, 3 1 Hz)
    int rateHz = 0;                    // from rateCode (decode); encode reads rateCode only
    bool kalmanFilter = false;         // 15
    bool firstFix2DAllowed = false;    // 14
    bool mode2DAllowed = false;        // 13
    bool geoPath = false;              // 12 (GeoS-5MP only)
    int ppsTimeScaleCode = 0;          // 11:9 (0 GPS, 1 UTC, 2 GLONASS, 3 UTC(SU), 4-7 reserved)
    bool ppsNegative = false;          // 8: 1PPS polarity
    bool ppsEnabled = false;           // 7
    bool searchUnusedSystems = false;  // 6: search signals of systems not in use
    bool sbas = false;                 // 4
    bool qzss = false;                 // 3
    bool galileo = false;              // 2
    bool gps = false;                  // 1
    bool glonass = false;              // 0
    static constexpr std::uint32_t kReservedMask =
            (1u << 31) | (1u << 29) | (1u << 20) | (3u << 16) | (1u << 5);

    static ConfigRegister1 decode(std::uint32_t word);
    // The word from the fields above; the reserved bits are taken from `raw` (a decoded word
    // keeps them, so encode(decode(w)) == w; a word filled in field by field has none).
    EncodedWord encode() const;
    std::string_view dynamicsName() const;     // "auto", "pedestrian_car", ... or "undefined"
    std::string_view ppsTimeScaleName() const; // "GPS", "UTC", "GLONASS", "UTC(SU)", "reserved"
    void writeJson(JsonWriter &w) const;
};

// Table 9: receiver configuration register #2.
struct ConfigRegister2 {
    std::uint32_t raw = 0;
    std::uint16_t receiverTypeCode = 0; // 31:16
    int datumCode = 0;                  // 15:14 (0 WGS-84, 1 PZ-90.11, 2 user-defined, 3 undefined)
    bool differentialAllowed = false;   // 8
    bool sbasTestModeAllowed = false;   // 4: use SBAS corrections flagged as test mode
    bool useAllSatellites = false;      // 3: 0 only satellites with corrections, 1 all
    bool sbasPrnAuto = false;           // 2: 0 set by the user, 1 automatic
    static constexpr std::uint32_t kReservedMask = (0x1Fu << 9) | (7u << 5) | 3u;

    static ConfigRegister2 decode(std::uint32_t word);
    // The word from the fields above; the reserved bits are taken from `raw` (a decoded word
    // keeps them, so encode(decode(w)) == w; a word filled in field by field has none).
    EncodedWord encode() const;
    // "GeoS-5M", "GeoS-5MR", "GeoS-5MH", "GeoS-5MP"; empty for a code not in table 9.
    std::string_view receiverType() const;
    std::string_view datumName() const; // "WGS-84", "PZ-90.11", "user", "undefined"
    void writeJson(JsonWriter &w) const;
};

// Rate code of table 8 / NQUERY (0 10 Hz, 1 5 Hz, 2 2 Hz, 3 1 Hz) → Hz; 0 for others.
int rateCodeToHz(int code);
// The inverse: Hz (10, 5, 2, 1) → rate code; -1 for others.
int rateHzToCode(int hz);

} // namespace gnss::geostar
