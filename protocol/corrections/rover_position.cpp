#include "corrections/rover_position.h"

namespace gnss::corrections {

namespace {

int ggaQuality(FixType f) {
    switch (f) {
    case FixType::None: return 0;
    case FixType::Dgnss: return 2;
    case FixType::RtkFixed: return 4;
    case FixType::RtkFloat: return 5;
    case FixType::Estimated: return 6;
    case FixType::Manual: return 7;
    case FixType::Simulator: return 8;
    default: return 1;
    }
}

} // namespace

std::optional<ntrip::GgaPosition> ggaPositionOf(const Epoch &e) {
    if (!e.lat || !e.lon || e.fix == FixType::None) return std::nullopt;
    ntrip::GgaPosition p;
    p.latDeg = *e.lat;
    p.lonDeg = *e.lon;
    p.altitudeMsl = e.altMsl.value_or(0);
    p.geoidSeparation = e.geoidSep.value_or(0);
    p.satellites = e.satsUsed.value_or(p.satellites);
    p.hdop = e.hdop.value_or(p.hdop);
    p.quality = ggaQuality(e.fix);
    return p;
}

} // namespace gnss::corrections
