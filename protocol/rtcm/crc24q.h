#pragma once
// CRC-24Q: the checksum closing every RTCM 3 frame (also Qualcomm's, and LTE's CRC-24A).
// Polynomial 0x1864CFB, initial value 0, no reflection, no final XOR; computed over the three
// header bytes and the payload. Check value: crc24q("123456789") == 0xCDE703.
#include <cstddef>
#include <cstdint>

namespace gnss::rtcm {

std::uint32_t crc24q(const std::uint8_t *data, std::size_t size, std::uint32_t crc = 0);

} // namespace gnss::rtcm
