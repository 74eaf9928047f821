#include "sim/sky_model.h"

#include "core/wgs84.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gnss::sim {

namespace {

constexpr double kDeg = wgs84::kDegree;
constexpr double kGm = 3.986004418e14;         // m^3/s^2
constexpr double kEarthRate = 7.2921151467e-5; // rad/s
constexpr double kGeoRadius = 42164172.0;

// Real GLONASS slot → frequency channel plan (antipodal slots share a channel).
constexpr std::array<int, 24> kGlonassChannels = {1,  -4, 5, 6,  1, -4, 5, 6, -2, -7, 0, -1,
                                                  -2, -7, 0, -1, 4, -3, 3, 2, 4,  -3, 3, 2};

struct Walker {
    Constellation system;
    int firstPrn;
    int planes;
    int perPlane;
    double radius;
    double inclinationDeg;
};

constexpr std::array<Walker, 4> kWalkers = {{
        {Constellation::Gps, 1, 6, 4, 26559700.0, 55.0},
        {Constellation::Glonass, 1, 3, 8, 25508200.0, 64.8},
        {Constellation::Galileo, 1, 3, 8, 29599800.0, 56.0},
        {Constellation::BeiDou, 19, 3, 8, 27906100.0, 55.0},
}};

struct Geo {
    int prn;
    double lonDeg;
};
// EGNOS, SDCM and WAAS/GAGAN satellites (a plausible set, not the current one).
constexpr std::array<Geo, 6> kSbas = {
        {{120, -15.5}, {123, 31.5}, {125, -16.0}, {136, 5.0}, {140, 95.0}, {141, 167.0}}};

void ecefOfObserver(const Observer &o, double &x, double &y, double &z) {
    const wgs84::Ecef e = wgs84::toEcef({o.latDeg, o.lonDeg, o.altMsl + o.geoidSep});
    x = e.x;
    y = e.y;
    z = e.z;
}

double gaussian(std::mt19937 &rng) {
    std::normal_distribution<double> d(0.0, 1.0);
    return d(rng);
}

} // namespace

char modeIndicator(FixKind k) {
    switch (k) {
    case FixKind::None: return 'N';
    case FixKind::Autonomous: return 'A';
    case FixKind::Differential: return 'D';
    case FixKind::Float: return 'F';
    case FixKind::Fixed: return 'R';
    case FixKind::Estimated: return 'E';
    }
    return 'N';
}

int ggaQuality(FixKind k) {
    switch (k) {
    case FixKind::None: return 0;
    case FixKind::Autonomous: return 1;
    case FixKind::Differential: return 2;
    case FixKind::Float: return 5;
    case FixKind::Fixed: return 4;
    case FixKind::Estimated: return 6;
    }
    return 0;
}

double horizontalSigma(FixKind k) {
    switch (k) {
    case FixKind::None: return 0;
    case FixKind::Autonomous: return 1.2;
    case FixKind::Differential: return 0.45;
    case FixKind::Float: return 0.15;
    case FixKind::Fixed: return 0.008;
    case FixKind::Estimated: return 3.0;
    }
    return 0;
}

bool UseMask::enabled(Constellation c) const {
    switch (c) {
    case Constellation::Gps: return gps;
    case Constellation::Glonass: return glonass;
    case Constellation::Galileo: return galileo;
    case Constellation::BeiDou: return beidou;
    case Constellation::Sbas: return sbas;
    default: return false;
    }
}

double SkyModel::meanMotion(double radius) {
    return std::sqrt(kGm / (radius * radius * radius));
}

SkyModel::SkyModel(std::uint32_t seed, Observer observer) : observer_(observer), rng_(seed) {
    std::uniform_real_distribution<double> jitter(-4.0 * kDeg, 4.0 * kDeg);
    // A random instant of the constellations' day, so different seeds see different skies.
    std::uniform_real_distribution<double> day(0.0, 2 * wgs84::kPi);
    const double skyOffset = day(rng_);
    for (const Walker &w : kWalkers) {
        for (int p = 0; p < w.planes; ++p) {
            for (int k = 0; k < w.perPlane; ++k) {
                Orbit o{};
                o.system = w.system;
                o.prn = w.firstPrn + p * w.perPlane + k;
                o.radius = w.radius;
                o.inclination = w.inclinationDeg * kDeg;
                o.raan = 2 * wgs84::kPi * p / w.planes + skyOffset;
                o.phase = 2 * wgs84::kPi * k / w.perPlane +
                          2 * wgs84::kPi * p / (w.planes * w.perPlane) + jitter(rng_);
                if (w.system == Constellation::Glonass)
                    o.glonassChannel = kGlonassChannels[static_cast<std::size_t>(o.prn - 1)];
                orbits_.push_back(o);
            }
        }
    }
    for (const Geo &g : kSbas) {
        Orbit o{};
        o.system = Constellation::Sbas;
        o.prn = g.prn;
        o.radius = kGeoRadius;
        o.lonGeo = g.lonDeg * kDeg;
        orbits_.push_back(o);
    }
    std::uniform_real_distribution<double> acquire(0.5, 8.0);
    std::uniform_real_distribution<double> bias(-2.5, 2.5);
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
        acquireDelay_.push_back(acquire(rng_));
        snrBias_.push_back(bias(rng_));
    }
}

void SkyModel::look(const Orbit &o, double time, double &el, double &az) const {
    double x, y, z;
    if (o.lonGeo != 0.0 || o.radius == kGeoRadius) {
        x = o.radius * std::cos(o.lonGeo);
        y = o.radius * std::sin(o.lonGeo);
        z = 0;
    } else {
        const double u = o.phase + meanMotion(o.radius) * time;
        const double xp = o.radius * std::cos(u), yp = o.radius * std::sin(u);
        const double xi = xp * std::cos(o.raan) - yp * std::cos(o.inclination) * std::sin(o.raan);
        const double yi = xp * std::sin(o.raan) + yp * std::cos(o.inclination) * std::cos(o.raan);
        const double zi = yp * std::sin(o.inclination);
        const double th = kEarthRate * time;
        x = xi * std::cos(th) + yi * std::sin(th);
        y = -xi * std::sin(th) + yi * std::cos(th);
        z = zi;
    }
    double ox, oy, oz;
    ecefOfObserver(observer_, ox, oy, oz);
    const double dx = x - ox, dy = y - oy, dz = z - oz;
    const double phi = observer_.latDeg * kDeg, lam = observer_.lonDeg * kDeg;
    const double e = -std::sin(lam) * dx + std::cos(lam) * dy;
    const double n = -std::sin(phi) * std::cos(lam) * dx - std::sin(phi) * std::sin(lam) * dy +
                     std::cos(phi) * dz;
    const double up = std::cos(phi) * std::cos(lam) * dx + std::cos(phi) * std::sin(lam) * dy +
                      std::sin(phi) * dz;
    el = std::atan2(up, std::hypot(e, n)) / kDeg;
    az = std::atan2(e, n) / kDeg;
    if (az < 0) az += 360.0;
}

std::vector<SimSatellite> SkyModel::geometry(double time) const {
    std::vector<SimSatellite> out;
    for (const Orbit &o : orbits_) {
        SimSatellite s;
        s.system = o.system;
        s.prn = o.prn;
        s.glonassChannel = o.glonassChannel;
        look(o, time, s.elevation, s.azimuth);
        if (s.elevation > 0) out.push_back(s);
    }
    return out;
}

SkySnapshot SkyModel::update(double time, const UseMask &mask, FixKind fix, double trackingSince) {
    SkySnapshot snap;
    snap.time = time;
    for (std::size_t i = 0; i < orbits_.size(); ++i) {
        const Orbit &o = orbits_[i];
        SimSatellite s;
        s.system = o.system;
        s.prn = o.prn;
        s.glonassChannel = o.glonassChannel;
        if ((o.system == Constellation::Galileo && !mask.galileoHardware) ||
            (o.system == Constellation::BeiDou && !mask.beidouHardware))
            continue;
        look(o, time, s.elevation, s.azimuth);
        if (s.elevation <= 0) continue;
        const double sinEl = std::sin(s.elevation * kDeg);
        const double noise = gaussian(rng_);
        s.tracked = mask.enabled(o.system) && time - trackingSince >= acquireDelay_[i];
        if (s.tracked) {
            s.snr = std::clamp(27.0 + 21.0 * std::sqrt(sinEl) + snrBias_[i] + 0.8 * noise * noise_,
                               10.0, 55.0);
        }
        s.used = s.tracked && fix != FixKind::None && s.elevation >= mask.elevationMask &&
                 s.snr >= mask.snrMask && (o.system != Constellation::Sbas || mask.sbasInSolution);
        snap.satellites.push_back(s);
    }
    std::vector<SimSatellite> used;
    for (const SimSatellite &s : snap.satellites)
        if (s.used) used.push_back(s);
    if (used.size() < 4) {
        fix = FixKind::None;
        for (SimSatellite &s : snap.satellites) s.used = false;
        used.clear();
    }
    snap.used = static_cast<int>(used.size());
    snap.fix = fix;
    if (fix != FixKind::None) snap.dops = computeDops(used);

    // Normalised Gauss-Markov errors (tau 30 s) scaled by the current accuracy: the error
    // wanders smoothly, and shrinks at once when the fix improves (float → fixed).
    const double dt = lastTime_ < 0 ? 1.0 : std::max(0.0, time - lastTime_);
    lastTime_ = time;
    const double a = std::exp(-dt / 30.0), b = std::sqrt(1 - a * a);
    errN_ = a * errN_ + b * gaussian(rng_);
    errE_ = a * errE_ + b * gaussian(rng_);
    errU_ = a * errU_ + b * gaussian(rng_);
    const double h = horizontalSigma(fix);
    snap.sigmaNorth = h * std::min(snap.dops.hdop, 20.0) / std::sqrt(2.0);
    snap.sigmaEast = snap.sigmaNorth;
    snap.sigmaUp = h * 1.6 * std::min(snap.dops.vdop, 20.0);
    snap.errNorth = errN_ * snap.sigmaNorth * noise_;
    snap.errEast = errE_ * snap.sigmaEast * noise_;
    snap.errUp = errU_ * snap.sigmaUp * noise_;
    snap.sigmaVel = fix == FixKind::None ? 0 : (fix == FixKind::Fixed ? 0.01 : 0.04);
    snap.velNorth = snap.sigmaVel * gaussian(rng_) * noise_;
    snap.velEast = snap.sigmaVel * gaussian(rng_) * noise_;
    snap.velUp = snap.sigmaVel * 1.5 * gaussian(rng_) * noise_;

    const wgs84::MetresPerDegree per = wgs84::metresPerDegree(observer_.latDeg);
    snap.lat = observer_.latDeg + snap.errNorth / per.north;
    snap.lon = observer_.lonDeg + snap.errEast / per.east;
    snap.altMsl = observer_.altMsl + snap.errUp;
    snap.geoidSep = observer_.geoidSep;
    return snap;
}

void offsetGeodetic(double &latDeg, double &lonDeg, double &height, double north, double east,
                    double up) {
    const wgs84::MetresPerDegree per = wgs84::metresPerDegree(latDeg);
    latDeg += north / per.north;
    lonDeg += east / per.east;
    height += up;
}

Dops computeDops(const std::vector<SimSatellite> &used) {
    Dops d;
    if (used.size() < 4) return d;
    // Normal matrix N = G^T G, rows of G = (-cos el sin az, -cos el cos az, -sin el, 1) (E N U t).
    double nm[4][8] = {};
    for (const SimSatellite &s : used) {
        const double el = s.elevation * kDeg, az = s.azimuth * kDeg;
        const double g[4] = {-std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az),
                             -std::sin(el), 1.0};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) nm[i][j] += g[i] * g[j];
    }
    for (int i = 0; i < 4; ++i) nm[i][4 + i] = 1.0;
    // Gauss-Jordan with partial pivoting.
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(nm[r][c]) > std::fabs(nm[p][c])) p = r;
        if (std::fabs(nm[p][c]) < 1e-12) return d; // degenerate geometry
        if (p != c)
            for (int k = 0; k < 8; ++k) std::swap(nm[p][k], nm[c][k]);
        const double inv = 1.0 / nm[c][c];
        for (int k = 0; k < 8; ++k) nm[c][k] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            const double f = nm[r][c];
            for (int k = 0; k < 8; ++k) nm[r][k] -= f * nm[c][k];
        }
    }
    const double qe = nm[0][4], qn = nm[1][5], qu = nm[2][6], qt = nm[3][7];
    auto cap = [](double v) { return std::min(std::sqrt(std::max(v, 0.0)), 99.9); };
    d.edop = cap(qe);
    d.ndop = cap(qn);
    d.vdop = cap(qu);
    d.tdop = cap(qt);
    d.hdop = cap(qe + qn);
    d.pdop = cap(qe + qn + qu);
    d.gdop = cap(qe + qn + qu + qt);
    return d;
}

} // namespace gnss::sim
