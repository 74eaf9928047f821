#pragma once
// SkyModel: a believable sky over a fixed observer, deterministic for a given seed.
//
// GPS, GLONASS, Galileo and BeiDou satellites fly circular orbits (Walker-like planes with each
// system's radius and inclination) and the Earth turns under them, which gives smooth
// elevation/azimuth tracks with rises and sets. SBAS satellites are geostationary. SNR grows with
// elevation plus noise. The position is the observer's plus a Gauss-Markov error scaled by the
// fix's accuracy and the DOP of the satellites used; DOPs come from the used geometry
// (4x4 least squares, (G^T G)^-1).
#include "core/satellite.h"

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace gnss::sim {

struct Observer {
    double latDeg = 55.7512; // Moscow: the home of two of the three receivers
    double lonDeg = 37.6184;
    double altMsl = 152.0;  // metres above the geoid
    double geoidSep = 14.6; // geoid above the ellipsoid, metres
};

// What the receiver's engine currently achieves (chosen by the receiver's fix sequence).
enum class FixKind : std::uint8_t { None, Autonomous, Differential, Float, Fixed, Estimated };
char modeIndicator(FixKind k);     // N A D F R E (RMC/VTG/PNVG mode indicator)
int ggaQuality(FixKind k);         // 0 1 2 5 4 6
double horizontalSigma(FixKind k); // typical 1-sigma horizontal error, metres

struct SimSatellite {
    Constellation system = Constellation::Unknown;
    int prn = 0;            // PRN, GLONASS slot, SBAS PRN (120..158)
    int glonassChannel = 0; // GLONASS frequency number (-7..6)
    double elevation = 0;   // degrees
    double azimuth = 0;     // degrees, 0..360
    double snr = 0;         // dB-Hz (0 = not tracked)
    bool tracked = false;   // a signal is locked (SNR valid)
    bool used = false;      // in the solution
};

struct Dops {
    double gdop = 99.9, pdop = 99.9, hdop = 99.9, vdop = 99.9, tdop = 99.9, ndop = 99.9,
           edop = 99.9;
};

// Which satellites the receiver may use (the receiver's settings).
struct UseMask {
    bool gps = true, glonass = true, galileo = true, beidou = true, sbas = true;
    // Systems the receiver's hardware cannot receive do not appear at all (not even in GSV).
    bool galileoHardware = true, beidouHardware = true;
    double elevationMask = 5;    // degrees
    double snrMask = 0;          // dB-Hz
    bool sbasInSolution = false; // SBAS ranging (most receivers only use SBAS corrections)
    bool enabled(Constellation c) const;
};

struct SkySnapshot {
    double time = 0;                      // seconds since the model's epoch
    std::vector<SimSatellite> satellites; // in view (elevation > 0), sorted by system then PRN
    int used = 0;
    Dops dops;
    FixKind fix = FixKind::None;
    // Position (valid when fix != None): degrees, metres.
    double lat = 0, lon = 0, altMsl = 0, geoidSep = 0;
    double errNorth = 0, errEast = 0, errUp = 0;       // the position error drawn (metres)
    double velNorth = 0, velEast = 0, velUp = 0;       // m/s (the observer is static: noise only)
    double sigmaNorth = 0, sigmaEast = 0, sigmaUp = 0; // 1-sigma, metres
    double sigmaVel = 0;                               // m/s
};

class SkyModel {
public:
    explicit SkyModel(std::uint32_t seed, Observer observer = {});

    const Observer &observer() const { return observer_; }
    // Computes the sky at `time` (seconds since the model's epoch) with the given mask and fix.
    // Noise is drawn from the model's generator: call once per epoch, in time order.
    SkySnapshot update(double time, const UseMask &mask, FixKind fix, double trackingSince = -1e9);
    // The satellites' geometry only (no noise drawn, no state changed): for almanac reports.
    std::vector<SimSatellite> geometry(double time) const;

    // The orbit of one satellite (for almanac/ephemeris reports).
    struct Orbit {
        Constellation system;
        int prn;
        double radius;      // metres
        double inclination; // radians
        double raan;        // radians, at the model's epoch (inertial)
        double phase;       // argument of latitude at the epoch, radians
        double lonGeo;      // geostationary longitude (radians) when radius is GEO, else 0
        int glonassChannel;
    };
    const std::vector<Orbit> &orbits() const { return orbits_; }
    static double meanMotion(double radius); // rad/s

    std::mt19937 &random() { return rng_; }
    // How much of the noise reaches the output: 1 (the default) as modelled, 0 the truth (the
    // observer's position, C/N0 by elevation alone). The same numbers are drawn either way.
    void setNoise(double scale) { noise_ = scale; }

private:
    void look(const Orbit &o, double time, double &el, double &az) const;

    Observer observer_;
    std::vector<Orbit> orbits_;
    std::vector<double> acquireDelay_; // per orbit: seconds after tracking starts
    std::vector<double> snrBias_;      // per orbit: antenna/satellite power difference
    std::mt19937 rng_;
    double errN_ = 0, errE_ = 0, errU_ = 0, lastTime_ = -1;
    double noise_ = 1;
};

// Geodetic position `north`/`east`/`up` metres away from (latDeg, lonDeg, height).
void offsetGeodetic(double &latDeg, double &lonDeg, double &height, double north, double east,
                    double up);

// Least-squares DOPs from unit line-of-sight vectors (el/az in degrees). Fewer than 4: 99.9.
Dops computeDops(const std::vector<SimSatellite> &used);

} // namespace gnss::sim
