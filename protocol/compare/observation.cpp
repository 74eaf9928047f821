#include "compare/observation.h"

#include "state/epoch.h"

namespace gnss::compare {

std::optional<Observation> Observation::of(const Epoch &e) {
    if (!e.time) return std::nullopt;
    Observation o;
    // Milliseconds: receivers print 1 to 3 decimals of the same instant.
    o.timeMs = (e.time->nanos + 500'000) / 1'000'000;
    o.fix = e.fix;
    o.lat = e.lat;
    o.lon = e.lon;
    o.height = e.altEllipsoid() ? e.altEllipsoid() : e.altMsl;
    o.levels.reserve(e.satellites.size());
    for (const SatelliteInView &s : e.satellites)
        if (s.snr && *s.snr > 0) o.levels.push_back({s.sat, s.signalId, *s.snr});
    return o;
}

} // namespace gnss::compare
