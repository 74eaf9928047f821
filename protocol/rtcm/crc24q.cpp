#include "crc24q.h"

#include <array>

namespace gnss::rtcm {
namespace {

constexpr std::uint32_t kPolynomial = 0x1864CFB;

// One entry per byte value: the CRC register after shifting that byte through. Built at compile
// time so there is no initialisation order to worry about.
constexpr std::array<std::uint32_t, 256> makeTable() {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t b = 0; b < 256; ++b) {
        std::uint32_t crc = b << 16;
        for (int i = 0; i < 8; ++i) {
            crc <<= 1;
            if (crc & 0x1000000) crc ^= kPolynomial;
        }
        t[b] = crc & 0xFFFFFF;
    }
    return t;
}
constexpr auto kTable = makeTable();

} // namespace

std::uint32_t crc24q(const std::uint8_t *data, std::size_t size, std::uint32_t crc) {
    for (std::size_t i = 0; i < size; ++i)
        crc = ((crc << 8) & 0xFFFFFF) ^ kTable[((crc >> 16) ^ data[i]) & 0xFF];
    return crc;
}

} // namespace gnss::rtcm
