// Multiple Signal Messages (MSM1..MSM7) of every system: header decoded, body length checked.
#include "rtcm/message_decoders.h"

#include <bit>

namespace gnss::rtcm {
namespace {

// Per satellite and per cell bits of each MSM type's body (RTCM 10403.3, 3.5.6.3):
//   MSM1  sat: DF398 (10)                        cell: DF400 (15)
//   MSM2  sat: DF398 (10)                        cell: DF401 22, DF402 4, DF420 1
//   MSM3  sat: DF398 (10)                        cell: DF400 15, DF401 22, DF402 4, DF420 1
//   MSM4  sat: DF397 8, DF398 10                 cell: MSM3 + DF403 6
//   MSM5  sat: DF397 8, ext 4, DF398 10, DF399 14  cell: MSM4 + DF404 15
//   MSM6  sat: DF397 8, DF398 10                 cell: DF405 20, DF406 24, DF407 10, DF420 1,
//                                                      DF408 10
//   MSM7  sat: as MSM5                           cell: MSM6 + DF404 15
constexpr unsigned kSatBits[8] = {0, 10, 10, 10, 18, 36, 18, 36};
constexpr unsigned kCellBits[8] = {0, 15, 27, 42, 48, 63, 65, 80};

System systemOfMsm(unsigned number) {
    return static_cast<System>((number - 1071) / 10);
}

} // namespace

bool isMsm(unsigned number) {
    return number >= 1071 && number <= 1137 && number % 10 >= 1 && number % 10 <= 7;
}

std::size_t msmBodyBits(unsigned msmType, unsigned satellites, unsigned cells) {
    if (msmType < 1 || msmType > 7) return 0;
    return std::size_t(satellites) * kSatBits[msmType] + std::size_t(cells) * kCellBits[msmType];
}

// MSM header (169 bits + cell mask), then the body.
//
//   field                                   DF     bits
//   message number                          002    12   (read by decodeMessage)
//   reference station id                    003    12
//   epoch time: GPS TOW ms                  004    30   (Galileo 248, QZSS 428, BeiDou 427,
//                                                         SBAS and NavIC like GPS)
//            or GLONASS day of week         416     3
//               + GLONASS time of day ms    034    27
//   multiple message bit                    393     1
//   issue of data station (IODS)            409     3
//   reserved                                001     7
//   clock steering indicator                411     2
//   external clock indicator                412     2
//   divergence-free smoothing indicator     417     1
//   smoothing interval                      418     3
//   satellite mask                          394    64
//   signal mask                             395    32
//   cell mask                               396    nsat × nsig (≤ 64)
//   satellite data, signal data             ...    msmBodyBits()
void decodeMsm(BitReader &r, RtcmMessage &m) {
    MsmHeader h;
    h.system = systemOfMsm(m.number);
    h.msmType = m.number % 10;
    if (r.has(12)) m.station = h.station = static_cast<unsigned>(r.u(12));
    if (h.system == System::Glonass) {
        h.gloDayOfWeek = static_cast<unsigned>(r.u(3));
        h.epochMs = static_cast<std::uint32_t>(r.u(27));
    } else {
        h.epochMs = static_cast<std::uint32_t>(r.u(30));
    }
    h.multipleMessage = r.flag();
    h.iods = static_cast<unsigned>(r.u(3));
    r.skip(7);
    h.clockSteering = static_cast<unsigned>(r.u(2));
    h.externalClock = static_cast<unsigned>(r.u(2));
    h.smoothing = r.flag();
    h.smoothingInterval = static_cast<unsigned>(r.u(3));
    h.satelliteMask = r.u(64);
    h.signalMask = static_cast<std::uint32_t>(r.u(32));
    if (!r.ok()) {
        m.error = "truncated in the MSM header";
        return;
    }
    for (unsigned i = 0; i < 64; ++i)
        if (h.satelliteMask >> (63 - i) & 1) h.satellites[h.satelliteCount++] = std::uint8_t(i + 1);
    for (unsigned i = 0; i < 32; ++i)
        if (h.signalMask >> (31 - i) & 1) h.signalList[h.signalCount++] = std::uint8_t(i + 1);
    const unsigned cellBits = unsigned(h.satelliteCount) * h.signalCount;
    if (cellBits > 64) {
        // The standard caps the cell mask at 64 bits: such a header cannot be real.
        m.error = "more than 64 cells (satellites × signals)";
        return;
    }
    h.cellMask = r.u(cellBits);
    if (!r.ok()) {
        m.error = "truncated in the MSM cell mask";
        return;
    }
    h.cellCount = static_cast<std::uint8_t>(std::popcount(h.cellMask));
    if (!r.has(msmBodyBits(h.msmType, h.satelliteCount, h.cellCount))) {
        m.error = "MSM body shorter than its masks say";
        return;
    }
    m.body = h;
}

} // namespace gnss::rtcm
