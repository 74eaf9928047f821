#include "nemerix/sim/nemerix_sim_navdata.h"

#include "core/wgs84.h"

#include <cmath>

namespace gnss::sim::nemerixdata {

namespace {

using wgs84::kPi;
constexpr double kEarthRate = 7.2921151467e-5; // rad/s (IS-GPS-200)

const SkyModel::Orbit *gpsOrbit(const SkyModel &sky, int prn) {
    for (const SkyModel::Orbit &o : sky.orbits())
        if (o.system == Constellation::Gps && o.prn == prn) return &o;
    return nullptr;
}

// Radians → semicircles in [-1, 1).
double semicircles(double rad) {
    double s = std::fmod(rad / kPi, 2.0);
    if (s >= 1.0) s -= 2.0;
    if (s < -1.0) s += 2.0;
    return s;
}

// Orbit elements at the reference time `ref` (GPS time of week) for an orbit seen at sky time
// `refSim` (the sky model's time at that instant).
struct Elements {
    double sqrtA, i0, omega0, m0; // m^1/2, semicircles
};
Elements elementsOf(const SkyModel::Orbit &o, double refSim, double ref) {
    Elements e;
    e.sqrtA = std::sqrt(o.radius);
    e.i0 = o.inclination / kPi;
    // Longitude of the node at the reference time, then IS-GPS-200's Omega0 = that + wE * ref.
    e.omega0 = semicircles(o.raan - kEarthRate * refSim + kEarthRate * ref);
    e.m0 = semicircles(o.phase + SkyModel::meanMotion(o.radius) * refSim); // e = 0, omega = 0
    return e;
}

} // namespace

double almanacToa(double tow) {
    return std::floor(tow / 4096.0) * 4096.0;
}

double ephemerisToe(double tow) {
    return std::floor(tow / 7200.0) * 7200.0;
}

std::optional<nemerix::Almanac> almanac(const SkyModel &sky, int prn, double simTime, double tow,
                                        int) {
    const SkyModel::Orbit *o = gpsOrbit(sky, prn);
    if (!o) return std::nullopt;
    const double toa = almanacToa(tow);
    const Elements el = elementsOf(*o, simTime - (tow - toa), toa);
    using A = nemerix::Almanac;
    A a;
    a.sv = prn;
    const std::pair<A::Field, double> values[] = {
            {A::E, 0},
            {A::Health, 0},
            {A::Toa, toa},
            {A::DeltaI, el.i0 - 0.30}, // relative to i0 = 0.30 semicircles
            {A::OmegaDot, 0},
            {A::SqrtA, el.sqrtA},
            {A::Omega0, el.omega0},
            {A::Perigee, 0},
            {A::Mean, el.m0},
            {A::M0, el.m0},
            {A::Af0, 0},
            {A::Af1, 0},
    };
    for (const auto &[field, value] : values) a.setValue(field, value);
    return a;
}

std::vector<nemerix::EphemerisSubframe> ephemeris(const SkyModel &sky, int prn, double simTime,
                                                  double tow, int week) {
    const SkyModel::Orbit *o = gpsOrbit(sky, prn);
    if (!o) return {};
    const double toe = ephemerisToe(tow);
    const Elements el = elementsOf(*o, simTime - (tow - toe), toe);
    const double iodc = static_cast<int>(toe / 7200.0) & 0xFF; // issue of data: one per 2 hours
    // Field values of each subframe in its field order (EphemerisSubframe::Sf1/Sf2/Sf3).
    const double sf1[] = {static_cast<double>(week % 1024), 0, 0, 0, iodc, toe, 0, 0, 0};
    const double sf2[] = {iodc, 0, 0, el.m0, 0, 0, 0, el.sqrtA, toe};
    const double sf3[] = {0, el.omega0, 0, el.i0, 0, 0, 0, iodc, 0};
    std::vector<nemerix::EphemerisSubframe> out(3);
    for (int k = 0; k < 3; ++k) {
        nemerix::EphemerisSubframe &e = out[static_cast<std::size_t>(k)];
        e.sv = prn;
        e.subframe = k + 1;
        const double *v = k == 0 ? sf1 : k == 1 ? sf2 : sf3;
        for (int f = 0; f < static_cast<int>(nemerix::EphemerisSubframe::kMaxFields); ++f)
            e.setValue(f, v[f]);
    }
    return out;
}

nemerix::Ionosphere ionosphere(int sv) {
    // Typical broadcast Klobuchar coefficients.
    const double v[] = {1.1176e-8, 7.4506e-9, -5.9605e-8, -5.9605e-8, 90112, 0, -196608, -65536};
    nemerix::Ionosphere m;
    m.sv = sv;
    for (int i = 0; i < 8; ++i) m.setValue(i, v[i]);
    return m;
}

nemerix::UtcParameters utc(int sv, int week, int leapSeconds) {
    using U = nemerix::UtcParameters;
    U m;
    m.sv = sv;
    const std::pair<U::Field, double> values[] = {
            {U::A0, -9.3e-10},
            {U::A1, -8.9e-15},
            {U::DtLs, static_cast<double>(leapSeconds)},
            {U::Tot, 405504},
            {U::WnT, static_cast<double>(week % 256)},
            {U::WnLsf, 1929 % 256}, // the last leap second: end of 2016 (week 1929, day 7)
            {U::Dn, 7},
            {U::DtLsf, static_cast<double>(leapSeconds)},
            {U::NumBlocks, 2}, // 20-year blocks since 1980
            {U::TimeOffset, 0},
    };
    for (const auto &[field, value] : values) m.setValue(field, value);
    return m;
}

nemerix::ConstellationHealth health(const SkyModel &sky) {
    nemerix::ConstellationHealth m;
    for (int prn = 1; prn <= 32; ++prn) m.codes[m.count++] = gpsOrbit(sky, prn) ? "00" : "3F";
    return m;
}

} // namespace gnss::sim::nemerixdata
