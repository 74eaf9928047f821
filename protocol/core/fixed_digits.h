#pragma once
// Fields printed at fixed widths, read at once. Receivers print a GSV's satellite as
// "01,05,000,31" (id, elevation, azimuth, SNR) and a GSA's ids as "01,02,03,04": the text is
// loaded as two 8-byte words (overlapping when it is shorter than 16 bytes), every digit place is
// checked in a few word operations, and the numbers are taken from the words. Read field by field
// the same satellite costs four times the instructions (a view, a length switch and a digit test
// per field), and GSV and GSA sentences are two thirds of a multi-constellation log.
//
// Anything else (a blank, a sign, an empty field, another width) is refused, and the caller reads
// field by field: this is a shortcut for the common form, never a second definition of a field.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>

namespace gnss {

// A layout of digits ('d') and separators (','), 9 to 16 characters, with at most 8 fields.
template <std::size_t N> struct DigitLayout {
    static_assert(N >= 9 && N <= 16, "two words, the second overlapping the first");
    static constexpr std::size_t kMaxFields = 8;
    static constexpr std::size_t kLength = N;

    consteval DigitLayout(const char (&pattern)[N + 1]) {
        std::size_t field = 0;
        for (std::size_t pos = 0; pos < N; ++pos) {
            const char c = pattern[pos];
            if (c != 'd' && c != ',') throw "a layout holds digits ('d') and separators (',')";
            const std::size_t w = pos < 8 ? 0 : 1, shift = 8 * (pos % 8);
            const std::uint64_t zeroChar = c == 'd' ? '0' : ',';
            zero[w] |= zeroChar << shift;
            if (c == ',') {
                if (width[field] == 0) throw "every field holds a digit";
                ++field;
                continue;
            }
            digits[w] |= std::uint64_t{0xFF} << shift;
            if (width[field] == 0) first[field] = pos;
            ++width[field];
        }
        if (width[field] == 0) throw "every field holds a digit";
        fields = field + 1;
        if (fields > kMaxFields) throw "at most eight fields";
    }

    // Word w holds bytes [8w, 8w + 8): the pattern with '0' for each digit (XOR with it turns a
    // digit into 0 to 9 and a separator into 0), and 0xFF at each digit place.
    std::uint64_t zero[2] = {};
    std::uint64_t digits[2] = {};
    std::size_t fields = 0;
    std::size_t first[kMaxFields] = {};
    std::size_t width[kMaxFields] = {};
};
template <std::size_t N> DigitLayout(const char (&)[N]) -> DigitLayout<N - 1>;

namespace fixed_digits_detail {

// The digit at byte Pos of the text, from the two words: a constant shift.
template <std::size_t Pos> inline int digitAt(std::uint64_t w0, std::uint64_t w1) {
    if constexpr (Pos < 8)
        return static_cast<int>(w0 >> (8 * Pos) & 0xFF);
    else
        return static_cast<int>(w1 >> (8 * (Pos - 8)) & 0xFF);
}

template <auto L, std::size_t F, std::size_t... K>
inline int fieldValue(std::uint64_t w0, std::uint64_t w1, std::index_sequence<K...>) {
    int v = 0;
    ((v = v * 10 + digitAt<L.first[F] + K>(w0, w1)), ...);
    return v;
}

template <auto L, std::size_t... F>
inline void readFields(std::uint64_t w0, std::uint64_t w1, int *out, std::index_sequence<F...>) {
    ((out[F] = fieldValue<L, F>(w0, w1, std::make_index_sequence<L.width[F]>{})), ...);
}

} // namespace fixed_digits_detail

// Reads the L.fields numbers of `text` into `out` when it holds digits at every digit place of L;
// false otherwise. `text` must be L.fields whole fields with their separators (its only commas
// are the L.fields - 1 between them): then with digits at every digit place, and L.kLength bytes,
// the separators can only be at the separator places, so they are not looked at.
template <auto L> inline bool readFixedDigits(std::string_view text, int *out) {
    constexpr std::size_t n = L.kLength;
    if constexpr (std::endian::native != std::endian::little) {
        return false;
    } else {
        if (text.size() != n) return false;
        const char *const p = text.data();
        std::uint64_t w0, w1;
        std::memcpy(&w0, p, 8);
        std::memcpy(&w1, p + n - 8, 8);
        w1 >>= 8 * (16 - n); // bytes [8, n) at the bottom
        w0 ^= L.zero[0];
        w1 ^= L.zero[1];
        // A digit place holds 0 to 9 now: adding 0x76 leaves its top bit clear, and only then
        // (a byte that had its top bit set is caught by the OR with itself).
        constexpr std::uint64_t k76 = 0x7676767676767676ULL, kTop = 0x8080808080808080ULL;
        if ((((w0 + k76) | w0) & L.digits[0] & kTop) | (((w1 + k76) | w1) & L.digits[1] & kTop))
            return false;
        fixed_digits_detail::readFields<L>(w0, w1, out, std::make_index_sequence<L.fields>{});
        return true;
    }
}

} // namespace gnss
