#include "sim/rtcm_base_station.h"
#include "core/wgs84.h"

#include "rtcm/bit_writer.h"
#include "rtcm/rtcm_encoder.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace gnss::sim {

namespace {

constexpr double kLightMsPerMetre = 1000.0 / 299792458.0; // ms of light travel per metre
constexpr double kStartSecondOfDay = 10 * 3600.0;         // 10:00:00 UTC
constexpr double kLeapSeconds = 18;                       // GPS − UTC in 2024
constexpr double kGpsWeekStart = 5 * 86400.0;             // Friday in the GPS week
constexpr double kMoscowOffset = 3 * 3600.0;              // GLONASS time is UTC + 3 h
// How long the base has been tracking before the simulation starts, for the lock-time
// indicator: a base is left running, so its locks are long.
constexpr double kTrackingBeforeStart = 600;

// DF402, the MSM lock-time indicator: 0 below 32 ms, then one step per doubling, 15 from 524 s.
unsigned lockIndicator(double seconds) {
    const double ms = seconds * 1000;
    if (ms < 32) return 0;
    return static_cast<unsigned>(std::min(15.0, std::floor(std::log2(ms / 32)) + 1));
}

} // namespace

std::uint32_t RtcmBaseStation::gpsTowMs(double t) {
    const double s = std::fmod(kGpsWeekStart + kStartSecondOfDay + kLeapSeconds + t, 604800.0);
    return static_cast<std::uint32_t>(std::llround(s * 1000)) % 604800000u;
}

std::uint32_t RtcmBaseStation::glonassTodMs(double t) {
    const double s = std::fmod(kStartSecondOfDay + kMoscowOffset + t, 86400.0);
    return static_cast<std::uint32_t>(std::llround(s * 1000)) % 86400000u;
}

RtcmBaseStation::RtcmBaseStation(const BaseStationConfig &config)
    : config_(config),
      model_(config.seed, Observer{config.latDeg, config.lonDeg, config.height, 0}) {
    reconfigure(config);
}

void RtcmBaseStation::reconfigure(const BaseStationConfig &config) {
    if (config.latDeg != config_.latDeg || config.lonDeg != config_.lonDeg ||
        config.height != config_.height || config.seed != config_.seed)
        model_ = SkyModel(config.seed, Observer{config.latDeg, config.lonDeg, config.height, 0});
    config_ = config;
    config_.observationInterval = std::max(1, config.observationInterval);
    const wgs84::Ecef e = wgs84::toEcef({config.latDeg, config.lonDeg, config.height});
    ecef_[0] = e.x;
    ecef_[1] = e.y;
    ecef_[2] = e.z;
}

void RtcmBaseStation::startAt(double t) {
    now_ = t;
    nextEpoch_ = std::ceil(t - 1e-9);
}

void RtcmBaseStation::advance(double seconds) {
    if (seconds > 0) now_ += seconds; // advance(0) at the start sends the epoch of time 0
    while (nextEpoch_ <= now_ + 1e-9) {
        epoch(nextEpoch_);
        nextEpoch_ += 1;
    }
}

std::string RtcmBaseStation::takeOutput() {
    std::string out;
    out.swap(out_);
    return out;
}

void RtcmBaseStation::epoch(double t) {
    ++epochs_;
    sky_ = model_.update(t, UseMask{}, FixKind::Autonomous);
    const long second = std::lround(t);
    if (second % config_.observationInterval == 0) {
        const bool legacyObservations =
                config_.observations == BaseStationConfig::Observations::Legacy;
        for (const Constellation system : {Constellation::Gps, Constellation::Glonass}) {
            const bool more = system == Constellation::Gps;
            out_ += legacyObservations ? legacy(system, t, more) : msm4(system, t, more);
        }
    }
    if (config_.stationInterval > 0 && second % config_.stationInterval == 0) {
        rtcm::StationArp arp;
        arp.station = config_.stationId;
        arp.gps = arp.glonass = true;
        arp.x = ecef_[0];
        arp.y = ecef_[1];
        arp.z = ecef_[2];
        arp.antennaHeight = config_.antennaHeight;
        out_ += rtcm::encodeStationArp(arp);
    }
    if (config_.biasesInterval > 0 && second % config_.biasesInterval == 0) {
        rtcm::GlonassBiases b;
        b.station = config_.stationId;
        b.present = {true, false, false, false}; // L1 C/A only: a single-frequency base
        b.biases[0] = 0.0;
        out_ += rtcm::encodeGlonassBiases(b);
    }
}

std::vector<RtcmBaseStation::Cell> RtcmBaseStation::cells(Constellation system) {
    const double baseRadius =
            std::sqrt(ecef_[0] * ecef_[0] + ecef_[1] * ecef_[1] + ecef_[2] * ecef_[2]);
    std::normal_distribution<double> noise(0.0, 0.5);
    std::vector<Cell> cells;
    for (const SimSatellite &s : sky_.satellites) {
        if (s.system != system || s.elevation <= 0 || !s.tracked || s.prn < 1 || s.prn > 64)
            continue;
        double radius = 0;
        for (const SkyModel::Orbit &o : model_.orbits())
            if (o.system == system && o.prn == s.prn) radius = o.radius;
        if (radius <= baseRadius) continue;
        // Slant range to a satellite at `radius` seen at elevation el from `baseRadius`.
        const double el = wgs84::radians(s.elevation);
        const double sinEl = std::sin(el);
        const double range =
                std::sqrt(radius * radius - baseRadius * baseRadius * (1 - sinEl * sinEl)) -
                baseRadius * sinEl;
        cells.push_back({static_cast<std::uint8_t>(s.prn),
                         (range + noise(model_.random())) * kLightMsPerMetre, s.snr});
    }
    std::sort(cells.begin(), cells.end(),
              [](const Cell &a, const Cell &b) { return a.satellite < b.satellite; });
    return cells;
}

std::string RtcmBaseStation::legacy(Constellation system, double t, bool moreFollow) {
    const bool glonass = system == Constellation::Glonass;
    rtcm::LegacyObservables o;
    o.number = glonass ? 1010 : 1002;
    o.station = config_.stationId;
    o.epochMs = glonass ? glonassTodMs(t) : gpsTowMs(t);
    o.synchronous = moreFollow;
    for (const Cell &c : cells(system)) {
        if (o.satellites.size() == 31) break; // DF006: five bits
        rtcm::LegacySatellite sat;
        sat.id = c.satellite;
        // A GLONASS slot's frequency channel: the constellation pairs antipodal slots on one.
        if (glonass) sat.frequencyChannel = static_cast<int>((c.satellite * 5) % 14) - 7;
        const double metres = c.rangeMs / kLightMsPerMetre;
        sat.l1.pseudorange = metres;
        sat.l1.phaseRange = metres;
        sat.l1.lockTime = 127; // DF013: locked for more than 937 s
        sat.l1.cnr = c.snr;
        o.satellites.push_back(sat);
    }
    return rtcm::encodeLegacy(o);
}

std::string RtcmBaseStation::msm4(Constellation system, double t, bool moreFollow) {
    const bool glonass = system == Constellation::Glonass;
    const std::vector<Cell> cells = this->cells(system);
    std::uint64_t satelliteMask = 0;
    for (const Cell &c : cells) satelliteMask |= std::uint64_t(1) << (64 - c.satellite);
    const std::uint32_t signalMask = 1u << (32 - 2); // signal id 2: L1 C/A ("1C") in both
    const unsigned n = static_cast<unsigned>(cells.size());

    rtcm::BitWriter w;
    w.u(glonass ? 1084 : 1074, 12).u(config_.stationId, 12);
    if (glonass)
        w.u(kGlonassDayOfWeek, 3).u(glonassTodMs(t), 27);
    else
        w.u(gpsTowMs(t), 30);
    w.flag(moreFollow).u(0, 3).zeros(7).u(0, 2).u(0, 2).flag(false).u(0, 3);
    w.u(satelliteMask, 64).u(signalMask, 32);
    if (n > 0) w.u(n == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1, n); // every cell
    // Satellite data: rough range in whole ms (DF397), then its fraction in 1/1024 ms (DF398).
    std::vector<double> rough(n);
    for (unsigned i = 0; i < n; ++i) {
        rough[i] = std::round(cells[i].rangeMs * 1024) / 1024;
        w.u(static_cast<std::uint64_t>(std::floor(rough[i])), 8);
    }
    for (unsigned i = 0; i < n; ++i)
        w.u(static_cast<std::uint64_t>(std::llround((rough[i] - std::floor(rough[i])) * 1024)) &
                    1023,
            10);
    // Signal data (one cell per satellite): fine pseudorange (DF400, 2^-24 ms), fine phase range
    // (DF401, 2^-29 ms), lock time (DF402), half-cycle ambiguity (DF420), CNR (DF403, 1 dB-Hz).
    for (unsigned i = 0; i < n; ++i)
        w.s(std::llround((cells[i].rangeMs - rough[i]) * 16777216.0), 15);
    for (unsigned i = 0; i < n; ++i)
        w.s(std::llround((cells[i].rangeMs - rough[i]) * 536870912.0), 22);
    for (unsigned i = 0; i < n; ++i) w.u(lockIndicator(t + kTrackingBeforeStart), 4);
    for (unsigned i = 0; i < n; ++i) w.u(0, 1);
    for (unsigned i = 0; i < n; ++i)
        w.u(static_cast<std::uint64_t>(std::clamp(std::lround(cells[i].snr), 1L, 63L)), 6);
    return rtcm::frame(w.bytes());
}

} // namespace gnss::sim
