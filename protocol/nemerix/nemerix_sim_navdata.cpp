#include "nemerix_sim_navdata.h"

#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_ephemeris.h"

#include <cmath>
#include <numbers>

namespace gnss::sim::nemerixdata {

namespace {

constexpr double kPi = std::numbers::pi;
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

std::int64_t raw(double value, const nemerix::HexFieldDef &def) {
    std::string error;
    const auto r = nemerix::toRaw(value, def, error);
    return r ? *r : 0;
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

std::string hexFields(std::span<const nemerix::HexFieldDef> defs,
                      std::span<const std::int64_t> values) {
    std::string s;
    for (std::size_t i = 0; i < defs.size() && i < values.size(); ++i)
        s += "," + nemerix::formatHex(values[i], defs[i].bits);
    return s;
}

} // namespace

double almanacToa(double tow) {
    return std::floor(tow / 4096.0) * 4096.0;
}

double ephemerisToe(double tow) {
    return std::floor(tow / 7200.0) * 7200.0;
}

std::string almanac(const SkyModel &sky, int prn, double simTime, double tow, int) {
    const SkyModel::Orbit *o = gpsOrbit(sky, prn);
    if (!o) return {};
    const double toa = almanacToa(tow);
    const Elements el = elementsOf(*o, simTime - (tow - toa), toa);
    const auto f = nemerix::Almanac::fields();
    nemerix::Almanac a;
    a.sv = prn;
    using A = nemerix::Almanac;
    a.raw[A::E] = 0;
    a.raw[A::Health] = 0;
    a.raw[A::Toa] = raw(toa, f[A::Toa]);
    a.raw[A::DeltaI] = raw(el.i0 - 0.30, f[A::DeltaI]);
    a.raw[A::OmegaDot] = 0;
    a.raw[A::SqrtA] = raw(el.sqrtA, f[A::SqrtA]);
    a.raw[A::Omega0] = raw(el.omega0, f[A::Omega0]);
    a.raw[A::Perigee] = 0;
    a.raw[A::Mean] = raw(el.m0, f[A::Mean]);
    a.raw[A::M0] = raw(el.m0, f[A::M0]);
    a.raw[A::Af0] = 0;
    a.raw[A::Af1] = 0;
    const auto r = nemerix::encodeAlmanac(a);
    return r.ok() ? r.sentences.front() : std::string();
}

std::vector<std::string> ephemeris(const SkyModel &sky, int prn, double simTime, double tow,
                                   int week) {
    const SkyModel::Orbit *o = gpsOrbit(sky, prn);
    if (!o) return {};
    const double toe = ephemerisToe(tow);
    const Elements el = elementsOf(*o, simTime - (tow - toe), toe);
    const int iodc = static_cast<int>(toe / 7200.0) & 0xFF; // issue of data: one per 2 hours
    using E = nemerix::EphemerisSubframe;
    const auto f1 = E::fields(1), f2 = E::fields(2), f3 = E::fields(3);
    const std::int64_t sf1[] = {week % 1024, 0, 0, 0, iodc, raw(toe, f1[E::Toc]), 0, 0, 0};
    const std::int64_t sf2[] = {iodc,
                                0,
                                0,
                                raw(el.m0, f2[E::M0]),
                                0,
                                0,
                                0,
                                raw(el.sqrtA, f2[E::SqrtA]),
                                raw(toe, f2[E::Toe])};
    const std::int64_t sf3[] = {
            0, raw(el.omega0, f3[E::Omega0]), 0, raw(el.i0, f3[E::I0]), 0, 0, 0, iodc, 0};
    const std::string head = "PNMRX301," + std::to_string(prn) + ",";
    return {buildSentence(head + "1" + hexFields(f1, sf1)),
            buildSentence(head + "2" + hexFields(f2, sf2)),
            buildSentence(head + "3" + hexFields(f3, sf3))};
}

std::string ionosphere(int sv) {
    // Typical broadcast Klobuchar coefficients.
    const double v[] = {1.1176e-8, 7.4506e-9, -5.9605e-8, -5.9605e-8, 90112, 0, -196608, -65536};
    const auto f = nemerix::Ionosphere::fields();
    std::int64_t r[8];
    for (int i = 0; i < 8; ++i) r[i] = raw(v[i], f[i]);
    return buildSentence("PNMRX302," + std::to_string(sv) + hexFields(f, r));
}

std::string utc(int sv, int week, int leapSeconds) {
    using U = nemerix::UtcParameters;
    const auto f = U::fields();
    std::int64_t r[U::kFieldCount] = {};
    r[U::A0] = raw(-9.3e-10, f[U::A0]);
    r[U::A1] = raw(-8.9e-15, f[U::A1]);
    r[U::DtLs] = leapSeconds;
    r[U::Tot] = raw(405504, f[U::Tot]);
    r[U::WnT] = week % 256;
    r[U::WnLsf] = 1929 % 256; // the last leap second: end of 2016 (week 1929, day 7)
    r[U::Dn] = 7;
    r[U::DtLsf] = leapSeconds;
    r[U::NumBlocks] = 2; // 20-year blocks since 1980
    r[U::TimeOffset] = 0;
    return buildSentence("PNMRX303," + std::to_string(sv) + hexFields(f, r));
}

std::string health(const SkyModel &sky) {
    std::string s = "PNMRX304";
    for (int prn = 1; prn <= 32; ++prn) s += gpsOrbit(sky, prn) ? ",00" : ",3F";
    return buildSentence(s);
}

} // namespace gnss::sim::nemerixdata
