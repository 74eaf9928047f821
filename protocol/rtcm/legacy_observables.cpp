// Legacy RTK observables (RTCM 10403.3, 3.5.2 and 3.5.3): 1001-1004 GPS, 1009-1012 GLONASS.
#include "rtcm/legacy_fields.h"
#include "rtcm/message_decoders.h"

namespace gnss::rtcm {
namespace {

using namespace legacy;

// The per-satellite fields, in order (bits):
//   GPS      DF009 6, DF010 1, DF011 24, DF012 20, DF013 7  [DF014 8, DF015 8]
//            [DF016 2, DF017 14, DF018 20, DF019 7  [DF020 8]]
//   GLONASS  DF038 6, DF039 1, DF040 5, DF041 25, DF042 20, DF043 7  [DF044 7, DF045 8]
//            [DF046 2, DF047 14, DF048 20, DF049 7  [DF050 8]]
// [ambiguity, CNR] in the extended messages (1002, 1004, 1010, 1012), L2 in 1003/1004 and
// 1011/1012, the L2 CNR in 1004 and 1012.

std::optional<double> cnrOf(std::uint64_t raw) {
    if (raw == 0) return std::nullopt; // "not computed"
    return static_cast<double>(raw) * kCnrStep;
}

std::optional<double> phaseOf(double l1Range, std::int64_t raw) {
    if (raw == kInvalidPhase) return std::nullopt;
    return l1Range + static_cast<double>(raw) * kPhaseStep;
}

LegacySatellite readSatellite(BitReader &r, const LegacyObservables &o, const Widths &l) {
    LegacySatellite sat;
    sat.id = static_cast<unsigned>(r.u(6));
    sat.l1.code = static_cast<unsigned>(r.u(1));
    if (l.channel) sat.frequencyChannel = static_cast<int>(r.u(l.channel)) - 7;
    const double l1Raw = static_cast<double>(r.u(l.range)) * kRangeStep;
    const std::int64_t l1Phase = r.s(20);
    sat.l1.lockTime = static_cast<unsigned>(r.u(7));
    double l1Range = l1Raw;
    if (o.extended()) {
        sat.ambiguity = static_cast<unsigned>(r.u(l.ambiguity));
        l1Range += *sat.ambiguity * l.ambiguityMetres;
        sat.l1.cnr = cnrOf(r.u(8));
    }
    sat.l1.pseudorange = l1Range;
    sat.l1.phaseRange = phaseOf(l1Range, l1Phase);
    if (!o.hasL2()) return sat;
    LegacySignal l2;
    l2.code = static_cast<unsigned>(r.u(2));
    const std::int64_t l2Range = r.s(14);
    if (l2Range != kInvalidL2Range) l2.pseudorange = l1Range + double(l2Range) * kRangeStep;
    l2.phaseRange = phaseOf(l1Range, r.s(20));
    l2.lockTime = static_cast<unsigned>(r.u(7));
    if (o.extended()) l2.cnr = cnrOf(r.u(8));
    sat.l2 = l2;
    return sat;
}

} // namespace

bool isLegacyObservables(unsigned number) {
    return (number >= 1001 && number <= 1004) || (number >= 1009 && number <= 1012);
}

std::size_t legacyHeaderBits(unsigned number) {
    if (!isLegacyObservables(number)) return 0;
    return number >= 1009 ? 61 : 64; // DF034 is 27 bits, DF004 30
}

std::size_t legacySatelliteBits(unsigned number) {
    static constexpr std::size_t kGps[4] = {58, 74, 101, 125};
    static constexpr std::size_t kGlonass[4] = {64, 79, 107, 130};
    if (!isLegacyObservables(number)) return 0;
    return number >= 1009 ? kGlonass[number - 1009] : kGps[number - 1001];
}

// Code indicators (DF010, DF016, DF039, DF046) as RINEX 3 codes. GPS L1: C/A, P(Y) direct;
// L2: C/A or L2C (one code cannot tell: "X"), P(Y) direct, P(Y) cross-correlated, correlated
// P/Y (Z-tracking). GLONASS: C/A, P on both bands (2 and 3 reserved).
std::string_view legacySignalName(System system, unsigned band, unsigned code) {
    static constexpr std::string_view kGpsL1[] = {"1C", "1P"};
    static constexpr std::string_view kGpsL2[] = {"2X", "2P", "2D", "2W"};
    static constexpr std::string_view kGloL1[] = {"1C", "1P"};
    static constexpr std::string_view kGloL2[] = {"2C", "2P"};
    const bool glo = system == System::Glonass;
    if (band == 1 && code < 2) return glo ? kGloL1[code] : kGpsL1[code];
    if (band == 2 && code < (glo ? 2u : 4u)) return glo ? kGloL2[code] : kGpsL2[code];
    return {};
}

// Header (64 bits GPS, 61 GLONASS), then DF006 / DF035 satellites of legacySatelliteBits() each.
//
//   field                                   DF     bits
//   message number                          002    12   (read by decodeMessage)
//   reference station id                    003    12
//   GPS epoch time (TOW, ms)                004    30
//     or GLONASS epoch time (time of day)   034    27
//   synchronous GNSS flag                   005     1
//   number of satellites                    006/035 5
//   divergence-free smoothing indicator     007/036 1
//   smoothing interval                      008/037 3
void decodeLegacyObservables(BitReader &r, RtcmMessage &m) {
    LegacyObservables o;
    o.number = m.number;
    if (r.has(12)) m.station = o.station = static_cast<unsigned>(r.u(12));
    o.epochMs = static_cast<std::uint32_t>(r.u(o.system() == System::Glonass ? 27 : 30));
    o.synchronous = r.flag();
    const auto count = static_cast<unsigned>(r.u(5));
    o.smoothing = r.flag();
    o.smoothingInterval = static_cast<unsigned>(r.u(3));
    if (!r.ok()) {
        m.error = "truncated in the header";
        return;
    }
    if (!r.has(count * legacySatelliteBits(m.number))) {
        m.error = "shorter than its satellites";
        return;
    }
    const Widths &layout = o.system() == System::Glonass ? kGlonassWidths : kGpsWidths;
    o.satellites.reserve(count);
    for (unsigned i = 0; i < count; ++i) o.satellites.push_back(readSatellite(r, o, layout));
    m.body = std::move(o);
}

} // namespace gnss::rtcm
