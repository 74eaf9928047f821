// 1230: GLONASS L1 and L2 code-phase biases (what a rover needs to mix GLONASS receivers).
#include "rtcm/message_decoders.h"

namespace gnss::rtcm {

// 1230 GLONASS code-phase biases (32 bits + 16 per signal in the mask).
//
//   field                                   DF     bits
//   message number                          002    12   (read by decodeMessage)
//   reference station id                    003    12
//   GLONASS code-phase bias indicator       421     1
//   reserved                                001     3
//   GLONASS FDMA signals mask               422     4   (L1 C/A, L1 P, L2 C/A, L2 P; MSB first)
//   L1 C/A code-phase bias, 0.02 m          423    16 int  ┐
//   L1 P code-phase bias, 0.02 m            424    16 int  │ each only when its mask bit is set;
//   L2 C/A code-phase bias, 0.02 m          425    16 int  │ −32768 means "not valid"
//   L2 P code-phase bias, 0.02 m            426    16 int  ┘
void decodeGlonassBiases(BitReader &r, RtcmMessage &m) {
    GlonassBiases b;
    if (r.has(12)) m.station = b.station = static_cast<unsigned>(r.u(12));
    b.aligned = r.flag();
    r.skip(3);
    b.mask = static_cast<unsigned>(r.u(4));
    for (unsigned i = 0; i < 4; ++i) {
        b.present[i] = (b.mask >> (3 - i)) & 1;
        if (!b.present[i]) continue;
        const std::int64_t raw = r.s(16);
        if (raw != -32768)
            b.biases[i] = static_cast<double>(raw) / 50.0; // ÷ 50 prints 1.02, × 0.02 may not
    }
    if (!r.ok()) {
        m.error = "truncated";
        return;
    }
    m.body = b;
}

} // namespace gnss::rtcm
