#pragma once
// SoakSky: the standard NMEA output of a busy multi-constellation receiver for the soak program:
// 20 epochs a second, about 60 satellites in view (GPS, GLONASS, Galileo, BeiDou pools of 126
// satellites rising and setting on 12-hour passes), RMC, GGA, one GSA and the GSVs per system,
// UTC from 2024-03-15 10:00:00 on (the simulator's start) with the date rolling over at midnight.
// Deterministic: the same epoch index gives the same bytes.
#include <QByteArray>

#include <cstdint>
#include <random>

namespace gnss::soak {

class SoakSky {
public:
    static constexpr double kRateHz = 20.0;
    static constexpr int kPoolSize = 126;

    explicit SoakSky(std::uint32_t seed = 1);
    // The sentences of epoch `n` (at n / kRateHz simulated seconds), CR LF terminated.
    QByteArray epoch(std::int64_t n);
    // Satellites in view in the last epoch made.
    int inView() const { return inView_; }

private:
    std::mt19937 rng_;
    double phase_[kPoolSize], period_[kPoolSize], azimuth0_[kPoolSize];
    int inView_ = 0;
};

} // namespace gnss::soak
