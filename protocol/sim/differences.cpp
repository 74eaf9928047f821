#include "sim/differences.h"

#include "sim/sky_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace gnss::sim {

namespace {

std::optional<double> number(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    for (;;) {
        const auto at = s.find(sep);
        out.push_back(s.substr(0, at));
        if (at == std::string_view::npos) return out;
        s.remove_prefix(at + 1);
    }
}

std::optional<Constellation> constellationNamed(std::string_view name) {
    for (Constellation c : {Constellation::Gps, Constellation::Glonass, Constellation::Galileo,
                            Constellation::BeiDou, Constellation::Qzss, Constellation::Sbas}) {
        const std::string_view full = toString(c);
        const bool same = name.size() == full.size() &&
                          std::equal(name.begin(), name.end(), full.begin(), [](char a, char b) {
                              return std::toupper(static_cast<unsigned char>(a)) == b;
                          });
        if (same || (name.size() == 1 &&
                     std::toupper(static_cast<unsigned char>(name[0])) == rinexLetter(c)))
            return c;
    }
    return std::nullopt;
}

} // namespace

bool Differences::any() const {
    return east != 0 || north != 0 || up != 0 || !cn0.empty() || !drop.empty() || latency > 0;
}

double Differences::cn0Offset(Constellation c) const {
    double db = 0;
    for (const auto &[system, offset] : cn0)
        if (system == c || system == Constellation::Unknown) db += offset;
    return db;
}

std::optional<Differences> parseOffset(std::string_view text, Differences d, std::string &error) {
    const auto parts = split(text, ',');
    std::optional<double> e, n, u;
    if (parts.size() == 3) {
        e = number(parts[0]);
        n = number(parts[1]);
        u = number(parts[2]);
    }
    if (!e || !n || !u) {
        error = "expected EAST,NORTH,UP in metres (0.3,-0.2,0.5), got '" + std::string(text) + "'";
        return std::nullopt;
    }
    d.east = *e;
    d.north = *n;
    d.up = *u;
    return d;
}

std::optional<Differences> parseCn0Offset(std::string_view text, Differences d,
                                          std::string &error) {
    d.cn0.clear();
    if (const auto all = number(text)) {
        d.cn0.emplace_back(Constellation::Unknown, *all);
        return d;
    }
    for (std::string_view part : split(text, ',')) {
        const auto colon = part.find(':');
        const auto system = colon == std::string_view::npos
                                    ? std::nullopt
                                    : constellationNamed(part.substr(0, colon));
        const auto db =
                colon == std::string_view::npos ? std::nullopt : number(part.substr(colon + 1));
        if (!system || !db) {
            error = "expected DB or SYSTEM:DB[,SYSTEM:DB] (GPS:-3,GLONASS:2), got '" +
                    std::string(part) + "'";
            return std::nullopt;
        }
        d.cn0.emplace_back(*system, *db);
    }
    return d;
}

std::optional<Differences> parseDrop(std::string_view text, Differences d, std::string &error) {
    d.drop.clear();
    for (std::string_view label : split(text, ',')) {
        const auto system = label.empty() ? std::nullopt : constellationNamed(label.substr(0, 1));
        int prn = 0;
        const auto digits = label.size() > 1 ? label.substr(1) : std::string_view();
        const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), prn);
        if (!system || digits.empty() || ec != std::errc() || p != digits.data() + digits.size() ||
            prn <= 0) {
            error = "expected satellites as G05,R12,E31 (a system letter G R E C J S and a "
                    "number), got '" +
                    std::string(label) + "'";
            return std::nullopt;
        }
        d.drop.push_back({*system, prn});
    }
    return d;
}

void applyDifferences(const Differences &d, SkySnapshot &snap) {
    if (snap.fix != FixKind::None && (d.east != 0 || d.north != 0 || d.up != 0)) {
        offsetGeodetic(snap.lat, snap.lon, snap.altMsl, d.north, d.east, d.up);
        snap.errEast += d.east;
        snap.errNorth += d.north;
        snap.errUp += d.up;
    }
    if (!d.cn0.empty())
        for (SimSatellite &s : snap.satellites)
            if (s.tracked) s.snr = std::max(0.0, s.snr + d.cn0Offset(s.system));
    if (d.drop.empty()) return;
    auto &sats = snap.satellites;
    const auto dropped = [&](const SimSatellite &s) {
        return std::find(d.drop.begin(), d.drop.end(), SatelliteRef{s.system, s.prn}) !=
               d.drop.end();
    };
    for (const SimSatellite &s : sats)
        if (s.used && dropped(s)) --snap.used;
    sats.erase(std::remove_if(sats.begin(), sats.end(), dropped), sats.end());
}

} // namespace gnss::sim
