#pragma once
// Small value types shared by the decoders: time of day, calendar date.
#include <cstdint>
#include <string>

namespace gnss {

// UTC time of day with the precision the receiver printed.
struct TimeOfDay {
    std::int64_t nanos = 0;    // since 00:00:00
    std::uint8_t decimals = 0; // digits printed after the seconds' decimal point (0-9)

    int hour() const { return static_cast<int>(nanos / 3'600'000'000'000LL); }
    int minute() const { return static_cast<int>(nanos / 60'000'000'000LL % 60); }
    double seconds() const { return static_cast<double>(nanos % 60'000'000'000LL) / 1e9; }
    bool operator==(const TimeOfDay &o) const { return nanos == o.nanos; }
    // "hh:mm:ss.sss" with at least `minDecimals` and the received precision otherwise.
    std::string toString(int minDecimals = 3) const;
};

struct Date {
    int year = 0, month = 0, day = 0;
    bool operator==(const Date &o) const = default;
    std::string toString() const; // "YYYY-MM-DD"
};

} // namespace gnss
