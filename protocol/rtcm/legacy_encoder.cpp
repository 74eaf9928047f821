// Encoders of the legacy observables (1001-1004, 1009-1012): legacy_observables.cpp's mirror.
#include "rtcm/bit_writer.h"
#include "rtcm/legacy_fields.h"
#include "rtcm/rtcm_encoder.h"

#include <algorithm>
#include <cmath>

namespace gnss::rtcm {
namespace {

using namespace legacy;

std::int64_t steps(double metres, double step) {
    return std::llround(metres / step);
}

// The L1 pseudorange as DF011/DF041 and the ambiguity: the caller's ambiguity when an extended
// message has one, else whole light-ms (GLONASS: 2 ms) taken off; a range that fits the field
// of a message without ambiguity is sent as it is. `full` is what the decoder will read back.
struct L1Range {
    std::int64_t raw = 0;
    std::int64_t ambiguity = 0;
    double full = 0;
};

L1Range splitRange(const LegacySatellite &sat, bool extended, const Widths &w) {
    const double pr = sat.l1.pseudorange.value_or(0.0);
    L1Range r;
    if (extended && sat.ambiguity)
        r.ambiguity = *sat.ambiguity;
    else if (extended || steps(pr, kRangeStep) >= (std::int64_t(1) << w.range))
        r.ambiguity = static_cast<std::int64_t>(std::floor(pr / w.ambiguityMetres));
    r.raw = steps(pr - double(r.ambiguity) * w.ambiguityMetres, kRangeStep);
    r.full = double(r.raw) * kRangeStep + double(r.ambiguity) * w.ambiguityMetres;
    return r;
}

std::int64_t phaseField(const LegacySignal &s, double l1) {
    return s.phaseRange ? steps(*s.phaseRange - l1, kPhaseStep) : kInvalidPhase;
}

std::uint64_t cnrField(const LegacySignal &s) {
    return s.cnr ? static_cast<std::uint64_t>(std::max<std::int64_t>(steps(*s.cnr, kCnrStep), 0))
                 : 0;
}

void writeSatellite(BitWriter &w, const LegacyObservables &o, const LegacySatellite &sat) {
    const Widths &widths = o.system() == System::Glonass ? kGlonassWidths : kGpsWidths;
    const L1Range l1 = splitRange(sat, o.extended(), widths);
    w.u(sat.id, 6).u(sat.l1.code, 1);
    if (widths.channel)
        w.u(static_cast<std::uint64_t>(sat.frequencyChannel.value_or(0) + 7), widths.channel);
    w.u(static_cast<std::uint64_t>(l1.raw), widths.range).s(phaseField(sat.l1, l1.full), 20);
    w.u(sat.l1.lockTime, 7);
    if (o.extended()) w.u(static_cast<std::uint64_t>(l1.ambiguity), widths.ambiguity);
    if (o.extended()) w.u(cnrField(sat.l1), 8);
    if (!o.hasL2()) return;
    const LegacySignal l2 = sat.l2.value_or(LegacySignal{});
    w.u(l2.code, 2);
    w.s(l2.pseudorange ? steps(*l2.pseudorange - l1.full, kRangeStep) : kInvalidL2Range, 14);
    w.s(phaseField(l2, l1.full), 20).u(l2.lockTime, 7);
    if (o.extended()) w.u(cnrField(l2), 8);
}

} // namespace

std::vector<std::uint8_t> legacyPayload(const LegacyObservables &o) {
    BitWriter w;
    w.u(o.number, 12);
    if (!isLegacyObservables(o.number)) return w.bytes();
    const std::size_t count = std::min<std::size_t>(o.satellites.size(), 31);
    w.u(o.station, 12).u(o.epochMs, o.system() == System::Glonass ? 27 : 30);
    w.flag(o.synchronous).u(count, 5).flag(o.smoothing).u(o.smoothingInterval, 3);
    for (std::size_t i = 0; i < count; ++i) writeSatellite(w, o, o.satellites[i]);
    return w.bytes();
}

std::string encodeLegacy(const LegacyObservables &o) {
    return frame(legacyPayload(o));
}

} // namespace gnss::rtcm
