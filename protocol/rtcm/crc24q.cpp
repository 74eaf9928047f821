#include "rtcm/crc24q.h"

#include <array>

namespace gnss::rtcm {
namespace {

// The 24-bit register is kept in the top of a 32-bit one (low byte zero) so eight input bytes
// can be folded per step with eight tables ("slicing-by-8"): framing is mostly this loop.
constexpr std::uint32_t kPolynomial = 0x864CFB00; // 0x1864CFB without x^24, shifted up 8

using Tables = std::array<std::array<std::uint32_t, 256>, 8>;

// Built at compile time: no initialisation order to worry about.
constexpr Tables makeTables() {
    Tables t{};
    for (std::uint32_t b = 0; b < 256; ++b) {
        std::uint32_t reg = b << 24;
        for (int i = 0; i < 8; ++i) reg = (reg & 0x80000000u) ? (reg << 1) ^ kPolynomial : reg << 1;
        t[0][b] = reg;
    }
    for (std::size_t k = 1; k < 8; ++k)
        for (std::uint32_t b = 0; b < 256; ++b)
            t[k][b] = (t[k - 1][b] << 8) ^ t[0][t[k - 1][b] >> 24];
    return t;
}
constexpr Tables kT = makeTables();

inline std::uint32_t be32(const std::uint8_t *p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

} // namespace

std::uint32_t crc24q(const std::uint8_t *data, std::size_t size, std::uint32_t crc) {
    std::uint32_t reg = crc << 8;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        const std::uint32_t a = reg ^ be32(data + i);
        const std::uint32_t b = be32(data + i + 4);
        reg = kT[7][a >> 24] ^ kT[6][(a >> 16) & 0xFF] ^ kT[5][(a >> 8) & 0xFF] ^ kT[4][a & 0xFF] ^
              kT[3][b >> 24] ^ kT[2][(b >> 16) & 0xFF] ^ kT[1][(b >> 8) & 0xFF] ^ kT[0][b & 0xFF];
    }
    for (; i < size; ++i) reg = (reg << 8) ^ kT[0][(reg >> 24) ^ data[i]];
    return reg >> 8;
}

} // namespace gnss::rtcm
