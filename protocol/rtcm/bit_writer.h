#pragma once
// BitWriter: RTCM 3 fields into a payload, most significant bit first (BitReader's mirror).
// Values are cut to their field width, as a receiver's encoder would send them.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace gnss::rtcm {

class BitWriter {
public:
    // Unsigned field of 0..64 bits: the low `bits` bits of v.
    BitWriter &u(std::uint64_t v, unsigned bits) {
        for (unsigned i = bits; i-- > 0;) bit((v >> i) & 1);
        return *this;
    }
    // Two's complement field of 1..64 bits.
    BitWriter &s(std::int64_t v, unsigned bits) { return u(static_cast<std::uint64_t>(v), bits); }
    // Sign-magnitude field (GLONASS intS): sign bit, then |v| in bits − 1.
    BitWriter &sm(std::int64_t v, unsigned bits) {
        const auto magnitude = static_cast<std::uint64_t>(v < 0 ? -v : v);
        return u(v < 0 ? 1 : 0, 1).u(magnitude, bits - 1);
    }
    BitWriter &flag(bool b) { return u(b ? 1 : 0, 1); }
    // 8-bit characters (DF030 etc.).
    BitWriter &chars(std::string_view text) {
        for (const char c : text) u(static_cast<unsigned char>(c), 8);
        return *this;
    }
    // Zero bits (reserved fields, skipped body data).
    BitWriter &zeros(std::size_t bits) {
        for (std::size_t i = 0; i < bits; ++i) bit(false);
        return *this;
    }

    std::size_t bitCount() const { return bits_; }
    // The payload, padded with zero bits to a whole byte.
    const std::vector<std::uint8_t> &bytes() const { return bytes_; }

private:
    void bit(bool b) {
        if ((bits_ & 7) == 0) bytes_.push_back(0);
        if (b) bytes_.back() |= static_cast<std::uint8_t>(0x80 >> (bits_ & 7));
        ++bits_;
    }

    std::vector<std::uint8_t> bytes_;
    std::size_t bits_ = 0;
};

} // namespace gnss::rtcm
