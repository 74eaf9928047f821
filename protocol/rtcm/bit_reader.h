#pragma once
// BitReader: RTCM 3 fields out of a payload, most significant bit first.
//
// Reading past the end never touches memory outside the payload: the read returns 0 and the
// reader remembers it (ok() turns false), so a decoder reads all its fields straight through and
// checks once at the end whether the payload was long enough.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace gnss::rtcm {

class BitReader {
public:
    explicit BitReader(std::span<const std::uint8_t> data, std::size_t bitOffset = 0)
        : data_(data), pos_(bitOffset) {}

    // Unsigned field of 0..64 bits (DF types uint/bit).
    std::uint64_t u(unsigned bits) {
        if (bits == 0) return 0;
        if (bits > 64 || !has(bits)) return fail();
        std::uint64_t v = 0;
        std::size_t p = pos_;
        unsigned left = bits;
        // Whole bytes where aligned would be faster, but fields are rarely aligned and short.
        while (left > 0) {
            const unsigned bitInByte = unsigned(p & 7);
            const unsigned take = std::min(left, 8 - bitInByte);
            const unsigned byte = data_[p >> 3];
            const unsigned chunk = (byte >> (8 - bitInByte - take)) & ((1u << take) - 1);
            v = (v << take) | chunk;
            p += take;
            left -= take;
        }
        pos_ = p;
        return v;
    }

    // Two's complement field of 1..64 bits (DF type int).
    std::int64_t s(unsigned bits) {
        const std::uint64_t v = u(bits);
        if (bits == 0 || bits >= 64) return static_cast<std::int64_t>(v);
        const std::uint64_t sign = std::uint64_t(1) << (bits - 1);
        return static_cast<std::int64_t>(v ^ sign) - static_cast<std::int64_t>(sign);
    }

    // Sign-magnitude field of 2..64 bits (DF type intS, used by GLONASS ephemerides): the first
    // bit is the sign, the rest the magnitude.
    std::int64_t sm(unsigned bits) {
        if (bits < 2) return static_cast<std::int64_t>(u(bits));
        const bool negative = u(1) != 0;
        const auto magnitude = static_cast<std::int64_t>(u(bits - 1));
        return negative ? -magnitude : magnitude;
    }

    bool flag() { return u(1) != 0; }

    // `count` 8-bit characters (DF030, DF033, ...); fewer when the payload ends first.
    std::string chars(std::size_t count) {
        std::string out;
        if (!has(count * 8)) {
            fail();
            return out;
        }
        out.reserve(count);
        for (std::size_t i = 0; i < count; ++i) out.push_back(static_cast<char>(u(8)));
        return out;
    }

    void skip(std::size_t bits) {
        if (!has(bits))
            fail();
        else
            pos_ += bits;
    }

    bool has(std::size_t bits) const { return ok_ && pos_ + bits <= data_.size() * 8; }
    bool ok() const { return ok_; }
    std::size_t position() const { return pos_; }
    std::size_t bitsLeft() const { return ok_ ? data_.size() * 8 - pos_ : 0; }

private:
    std::uint64_t fail() {
        ok_ = false;
        pos_ = data_.size() * 8;
        return 0;
    }

    std::span<const std::uint8_t> data_;
    std::size_t pos_ = 0;
    bool ok_ = true;
};

} // namespace gnss::rtcm
