#pragma once
// RtcmBaseStation: the simulator as an RTK base station. From the same SkyModel the simulated
// receivers fly, it sends what a single-frequency GPS+GLONASS base (such as an NV08C-RTK in base
// mode) would: once a second an MSM4 for GPS (1074) and one for GLONASS (1084), the station's
// position (1005) and, every ten seconds, the GLONASS code-phase biases (1230).
//
// The MSMs are whole, not just headers: satellite masks hold the satellites above the horizon,
// pseudoranges come from the geometry (slant range from the orbit radius and elevation, plus
// half a metre of noise), carrier-phase ranges follow them, CNR is the sky model's SNR and the
// lock time grows with the run. Every frame carries a valid CRC-24Q.
//
// Driven like a Receiver (advance time, take the bytes), without commands: whatever a client
// sends to a base is ignored. Plain C++, deterministic for a seed.
#include "sim/sky_model.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gnss::sim {

struct BaseStationConfig {
    // The observables: MSM4 (1074 GPS, 1084 GLONASS), or the legacy extended L1 messages (1002,
    // 1010) that an NV08C-RTK base sends.
    enum class Observations { Msm4, Legacy };

    double latDeg = 55.7512; // the sky model's default observer
    double lonDeg = 37.6184;
    double height = 166.6;   // ellipsoidal height, metres
    unsigned stationId = 1;  // DF003, 0..4095
    std::uint32_t seed = 1;  // sky and noise
    int stationInterval = 1; // seconds between 1005s (0: none)
    int biasesInterval = 10; // seconds between 1230s (0: none)
    Observations observations = Observations::Msm4;
    int observationInterval = 1;         // seconds between observation epochs (1 or more)
    std::optional<double> antennaHeight; // the station as 1006 with it, 1005 without
};

class RtcmBaseStation {
public:
    explicit RtcmBaseStation(const BaseStationConfig &config = {});

    // Starts the clock at `t` (a receiver that becomes a base mid-run): the first epoch is the
    // first whole second from there.
    void startAt(double t);
    // Another position, station or rate from now on (time and the sky go on).
    void reconfigure(const BaseStationConfig &config);

    // Runs for `seconds` of simulated time: one epoch at every whole second reached (the first
    // at time 0).
    void advance(double seconds);
    // The frames sent since the last call, as bytes.
    std::string takeOutput();

    double time() const { return now_; }
    std::uint64_t epochs() const { return epochs_; }
    const BaseStationConfig &config() const { return config_; }
    // The sky of the last epoch (the satellites the MSMs describe).
    const SkySnapshot &lastSky() const { return sky_; }

    // GPS time of week and GLONASS time of day (ms) of simulated time `t`: the simulator's start
    // is 2024-03-15 10:00:00 UTC, a Friday, like the receivers'.
    static std::uint32_t gpsTowMs(double t);
    static std::uint32_t glonassTodMs(double t);
    static constexpr unsigned kGlonassDayOfWeek = 5; // Friday (DF416: 0 = Sunday)

private:
    void epoch(double t);
    struct Cell {
        std::uint8_t satellite; // MSM satellite id (GPS PRN, GLONASS slot)
        double rangeMs;         // pseudorange in light-milliseconds
        double snr;             // dB-Hz
    };
    // The satellites of `system` above the horizon, by id, with their ranges from the station.
    std::vector<Cell> cells(Constellation system);
    std::string msm4(Constellation system, double t, bool moreFollow);
    std::string legacy(Constellation system, double t, bool moreFollow);

    BaseStationConfig config_;
    SkyModel model_;
    SkySnapshot sky_;
    double ecef_[3] = {0, 0, 0};
    double now_ = 0;
    double nextEpoch_ = 0;
    std::uint64_t epochs_ = 0;
    std::string out_;
};

} // namespace gnss::sim
