#pragma once
// EpochRecord: what the log viewer's index keeps of one navigation epoch, 64 bytes (a 1 GB log
// at 10 Hz has about 770 000 of them). The full receiver state is not kept: it is rebuilt from
// the nearest checkpoint (LogIndex::stateAt).
#include "core/fix_type.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace gnss::logview {

inline constexpr std::int64_t kNoTime = std::numeric_limits<std::int64_t>::min();

// Flags of an epoch (EpochRecord::flags).
enum EpochFlag : std::uint32_t {
    kTimeKnown = 1u << 0,       // the epoch has a UTC time of day
    kDateKnown = 1u << 1,       // ... and a date (from RMC/ZDA, this epoch or an earlier one)
    kGapBefore = 1u << 2,       // data gap before it (time step well over the usual interval)
    kChecksumErrors = 1u << 3,  // sentences with a wrong checksum among its lines
    kDecodeErrors = 1u << 4,    // malformed sentences among its lines
    kJunk = 1u << 5,            // bytes that are no sentence (binary, noise) among its lines
    kTimeBack = 1u << 6,        // its time is before the previous epoch's: a reset or a jump
    kMidnight = 1u << 7,        // without a date: the time of day wrapped past midnight
    kDialectChange = 1u << 8,   // another receiver family's sentences start here
    kTimeMark = 1u << 9,        // the receiver reported a time mark (event input)
    kJammingChange = 1u << 10,  // the jamming flag changed
    kStationChange = 1u << 11,  // the base/DGPS station changed
    kFixChange = 1u << 12,      // the fix type differs from the previous epoch's
    kLinkGap = 1u << 13,        // the recording's index marks the link lost/back before it
    kTruncatedLines = 1u << 14, // lines cut short (a '$' inside) or too long among its lines
};

struct EpochRecord {
    std::uint64_t offset = 0;      // file offset of its first byte; it ends where the next begins
    std::int64_t utcMs = kNoTime;  // kDateKnown: ms since 1970-01-01 UTC; else ms since the
                                   // first day of the log (midnights counted); kNoTime: no time
    std::int64_t hostMs = kNoTime; // a recording's host time (FILE.idx) when it has one
    double lat = NAN, lon = NAN;   // degrees; NaN when there is no position
    float altMsl = NAN;            // metres above mean sea level
    float hdop = NAN;
    float speed = NAN;         // m/s over ground
    std::int32_t station = -1; // base (RTK) or DGPS station id; -1 none
    std::uint16_t flags = 0;
    std::uint8_t fix = 0;            // FixType
    std::uint8_t sats = 255;         // satellites used; 255 unknown
    std::uint8_t snr = 255;          // mean SNR of the satellites heard, dB-Hz; 255 none
    std::uint8_t dialect = 0;        // 1 + index in the registry of the vendor last heard; 0 none
    std::uint8_t jamming = 0;        // 0 unknown, 1 no, 2 yes
    std::uint8_t checksumErrors = 0; // sentences with a wrong checksum (saturates at 255)

    FixType fixType() const { return static_cast<FixType>(fix); }
    bool hasPosition() const { return !std::isnan(lat) && !std::isnan(lon); }
    bool has(EpochFlag f) const { return (flags & f) != 0; }
    bool hasTime() const { return utcMs != kNoTime; }
};
static_assert(sizeof(EpochRecord) == 64, "the index stays compact");

// "2024-03-15T10:00:00.100Z" (date known), "10:00:00.100" (time of day only; "+1d" after a
// midnight), "" (no time).
std::string formatTime(const EpochRecord &r);
// ms since 1970 → "2024-03-15T10:00:00.100Z".
std::string formatUtcMs(std::int64_t ms);

} // namespace gnss::logview
