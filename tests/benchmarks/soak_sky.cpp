#include "soak_sky.h"

#include "core/sentence_builder.h"
#include "core/wgs84.h"

#include <QDate>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gnss::soak {
namespace {

struct System {
    const char *talker;
    int systemId, pool, firstId, signalId;
};
// 32 + 24 + 30 + 40 = kPoolSize satellites; about half are above the horizon at any time.
constexpr System kSystems[] = {
        {"GP", 1, 32, 1, 1}, {"GL", 2, 24, 65, 1}, {"GA", 3, 30, 1, 7}, {"GB", 4, 40, 1, 1}};
using wgs84::kPi;
constexpr double kStartSecondOfDay = 10 * 3600.0; // as sim::Receiver::kStartSecondOfDay

struct InView {
    int id, elevation, azimuth, snr;
};

} // namespace

SoakSky::SoakSky(std::uint32_t seed) : rng_(seed) {
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < kPoolSize; ++i) {
        phase_[i] = u(rng_) * 2 * kPi;
        period_[i] = (11.0 + 2.0 * u(rng_)) * 3600.0; // a pass up and down: 5.5 to 6.5 h
        azimuth0_[i] = u(rng_) * 360.0;
    }
}

QByteArray SoakSky::epoch(std::int64_t n) {
    const double t = double(n) / kRateHz;
    const double utc = kStartSecondOfDay + t;
    const auto day = std::int64_t(std::floor(utc / 86400.0));
    const double sod = utc - double(day) * 86400.0;
    const int hh = int(sod / 3600), mm = int(std::fmod(sod, 3600.0) / 60);
    const double ss = std::fmod(sod, 60.0);
    const QDate date = QDate(2024, 3, 15).addDays(day);
    std::normal_distribution<double> noise(0.0, 1.0);
    // Position: 2 cm noise about a point in Moscow (1e-5 minute of latitude is about 2 cm).
    const double latMin = 50.6129 + noise(rng_) * 1e-5, lonMin = 32.2527 + noise(rng_) * 2e-5;

    QByteArray out;
    char b[160];
    auto add = [&](const std::string &body) {
        out += QByteArray::fromStdString(gnss::buildSentence(body));
        out += "\r\n";
    };
    std::snprintf(b, sizeof b,
                  "GNRMC,%02d%02d%05.2f,A,55%07.4f,N,037%07.4f,E,0.01,0.0,%02d%02d%02d,,,R,V", hh,
                  mm, ss, latMin, lonMin, date.day(), date.month(), date.year() % 100);
    add(b);
    std::snprintf(b, sizeof b,
                  "GNGGA,%02d%02d%05.2f,55%07.4f,N,037%07.4f,E,4,40,0.5,%.3f,M,14.4,M,1.0,0031", hh,
                  mm, ss, latMin, lonMin, 180.0 + noise(rng_) * 0.02);
    add(b);
    inView_ = 0;
    int orbit = 0;
    for (const System &sys : kSystems) {
        std::vector<InView> sats;
        for (int k = 0; k < sys.pool; ++k, ++orbit) {
            const double a = phase_[orbit] + 2 * kPi * t / period_[orbit];
            const double el = 90.0 * std::sin(a);
            if (el < 1.0) continue;
            const double az = std::fmod(azimuth0_[orbit] + 180.0 * std::cos(a) + 360.0, 360.0);
            const int snr = std::clamp(int(22 + el / 3 + noise(rng_)), 10, 55);
            sats.push_back({sys.firstId + k, int(el), int(az), snr});
        }
        inView_ += int(sats.size());
        // GSA: the 12 highest are used.
        std::vector<InView> byElevation = sats;
        std::sort(byElevation.begin(), byElevation.end(),
                  [](const InView &x, const InView &y) { return x.elevation > y.elevation; });
        std::string gsa = "GNGSA,A,3";
        for (int i = 0; i < 12; ++i) {
            gsa += ',';
            if (i < int(byElevation.size())) gsa += std::to_string(byElevation[size_t(i)].id);
        }
        add(gsa + ",1.0,0.5,0.8," + std::to_string(sys.systemId));
        const int count = int(sats.size());
        const int parts = std::max(1, (count + 3) / 4);
        for (int p = 0; p < parts; ++p) {
            std::snprintf(b, sizeof b, "%sGSV,%d,%d,%02d", sys.talker, parts, p + 1, count);
            std::string gsv = b;
            for (int k = p * 4; k < std::min(count, p * 4 + 4); ++k) {
                const InView &s = sats[size_t(k)];
                std::snprintf(b, sizeof b, ",%02d,%02d,%03d,%02d", s.id, s.elevation, s.azimuth,
                              s.snr);
                gsv += b;
            }
            add(gsv + "," + std::to_string(sys.signalId));
        }
    }
    return out;
}

} // namespace gnss::soak
