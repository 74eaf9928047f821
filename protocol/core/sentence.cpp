#include "core/sentence.h"

#include "core/hex_digit.h"
#include "core/refusal.h"

#include <array>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gnss {
namespace {

#if defined(__SSE2__)
// For each 8-bit mask of commas in 8 bytes: where they are (0 to 7, in order, as eight 16-bit
// lanes; the lanes past the count are 0) and how many.
struct CommaSlots {
    alignas(16) std::uint16_t offsets[8];
    std::size_t count;
};
// Made at compile time: parse() may run while other files' statics are being made.
constexpr auto kCommaSlots = [] {
    std::array<CommaSlots, 256> t{};
    for (unsigned m = 0; m < 256; ++m) {
        std::size_t c = 0;
        for (unsigned b = 0; b < 8; ++b)
            if (m >> b & 1u) t[m].offsets[c++] = static_cast<std::uint16_t>(b);
        t[m].count = c;
    }
    return t;
}();
#endif

} // namespace

std::string_view toString(ChecksumStatus s) {
    switch (s) {
    case ChecksumStatus::Ok: return "ok";
    case ChecksumStatus::Bad: return "bad";
    case ChecksumStatus::Missing: return "missing";
    }
    return "missing";
}

std::uint8_t nmeaChecksum(std::string_view body) {
    const char *p = body.data();
    std::size_t n = body.size();
    std::uint64_t acc = 0;
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        acc ^= w;
    }
    acc ^= acc >> 32;
    acc ^= acc >> 16;
    acc ^= acc >> 8;
    auto sum = static_cast<std::uint8_t>(acc);
    for (; i < n; ++i) sum ^= static_cast<std::uint8_t>(p[i]);
    return sum;
}

bool Sentence::parse(std::string_view line) {
    line_ = line;
    error_ = nullptr;
    fieldCount_ = 0;
    placeholder_ = false;
    address_ = {};
    if (line.size() < 2 || (line.front() != '$' && line.front() != '!')) {
        body_ = {};
        error_ = QT_TRANSLATE_NOOP("Refusal", "not a sentence");
        return false;
    }

    // Checksum: the last '*' and what follows it.
    std::string_view text = line.substr(1);
    const std::size_t star = text.rfind('*');
    if (star == std::string_view::npos) {
        body_ = text;
        checksumStatus_ = ChecksumStatus::Missing;
    } else {
        body_ = text.substr(0, star);
        std::string_view cs = text.substr(star + 1);
        while (!cs.empty() && cs.back() == ' ') cs.remove_suffix(1);
        const int hi = cs.size() == 2 ? hexDigitValue(cs[0]) : -1;
        const int lo = cs.size() == 2 ? hexDigitValue(cs[1]) : -1;
        if (hi >= 0 && lo >= 0) {
            declared_ = static_cast<std::uint8_t>(hi * 16 + lo);
            checksumStatus_ = ChecksumStatus::Ok; // compared below
        } else if (cs.size() <= 2) {
            // "*", "*xx", "*XX": a placeholder where a checksum would be (Nemerix examples).
            checksumStatus_ = ChecksumStatus::Missing;
            placeholder_ = true;
        } else {
            checksumStatus_ = ChecksumStatus::Bad;
            declared_ = 0;
        }
    }

    // One pass over the body: XOR for the checksum and the comma positions.
    const char *p = body_.data();
    const std::size_t n = body_.size();
    if (n > 65000) {
        error_ = QT_TRANSLATE_NOOP("Refusal", "sentence too long");
        return false;
    }
    // Field starts are written straight into start_: start_[k] = offset after comma k. The
    // capacity check runs once per 16-byte block while far from the limit.
    std::size_t ncommas = 0;
    bool overflow = false;
    std::size_t i = 0;
    auto addComma = [&](std::size_t pos) {
        if (ncommas >= kMaxFields) {
            overflow = true;
            return;
        }
        start_[ncommas++] = static_cast<std::uint16_t>(pos + 1);
    };
#if defined(__SSE2__)
    const __m128i comma = _mm_set1_epi8(',');
    const __m128i blankByte = _mm_set1_epi8(0x20);
    __m128i xacc = _mm_setzero_si128();
    __m128i blanks = _mm_setzero_si128();
    // Block `v` holds body bytes [at, at + 16), of which the lanes in `lanes` (a byte mask, and
    // the same as bits of `laneBits`) are not in an earlier block.
    auto block = [&](__m128i v, std::size_t at, __m128i lanes, unsigned laneBits) {
        xacc = _mm_xor_si128(xacc, _mm_and_si128(v, lanes));
        blanks = _mm_or_si128(blanks, _mm_and_si128(_mm_cmpeq_epi8(v, blankByte), lanes));
        unsigned mask =
                static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, comma))) & laneBits;
        if (ncommas + 16 <= kMaxFields) {
            // Each half of the mask stores its commas' positions at once, however many there
            // are (kCommaSlots; slots past the count are written over later): no loop whose end
            // a branch predictor would have to guess, a few times in every sentence.
            const __m128i base = _mm_set1_epi16(static_cast<short>(at + 1));
            const CommaSlots &lo = kCommaSlots[mask & 0xFF], &hi = kCommaSlots[mask >> 8];
            _mm_storeu_si128(
                    reinterpret_cast<__m128i *>(start_ + ncommas),
                    _mm_add_epi16(_mm_load_si128(reinterpret_cast<const __m128i *>(lo.offsets)),
                                  base));
            ncommas += lo.count;
            _mm_storeu_si128(
                    reinterpret_cast<__m128i *>(start_ + ncommas),
                    _mm_add_epi16(_mm_load_si128(reinterpret_cast<const __m128i *>(hi.offsets)),
                                  _mm_add_epi16(base, _mm_set1_epi16(8))));
            ncommas += hi.count;
        } else {
            for (; mask; mask &= mask - 1)
                addComma(at + static_cast<std::size_t>(__builtin_ctz(mask)));
        }
    };
    const __m128i all = _mm_set1_epi8(-1);
    for (; i + 16 <= n; i += 16)
        block(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p + i)), i, all, 0xFFFFu);
    if (i < n && n >= 16) {
        // The last 1 to 15 bytes: the body's last 16 bytes once more (nothing past the body is
        // read) with only the lanes not yet seen counted, instead of a loop byte by byte (half a
        // block on average, on every sentence).
        alignas(16) static constexpr std::uint8_t kTailLanes[32] = {
                0,    0,    0,    0,    0,    0,    0,    0,    0,    0,    0,
                0,    0,    0,    0,    0,    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
        const std::size_t fresh = n - i;
        block(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p + n - 16)), n - 16,
              _mm_loadu_si128(reinterpret_cast<const __m128i *>(kTailLanes + fresh)),
              0xFFFFu << (16 - fresh) & 0xFFFFu);
        i = n;
    }
    alignas(16) std::uint8_t lanes[16];
    _mm_store_si128(reinterpret_cast<__m128i *>(lanes), xacc);
    std::uint64_t lo, hi;
    std::memcpy(&lo, lanes, 8);
    std::memcpy(&hi, lanes + 8, 8);
    std::uint64_t folded = lo ^ hi;
    folded ^= folded >> 32;
    folded ^= folded >> 16;
    folded ^= folded >> 8;
    std::uint8_t sum = static_cast<std::uint8_t>(folded);
    bool blank = _mm_movemask_epi8(blanks) != 0;
#else
    std::uint8_t sum = 0;
    bool blank = false;
#endif
    for (; i < n; ++i) {
        const char c = p[i];
        sum ^= static_cast<std::uint8_t>(c);
        blank |= c == ' ';
        if (c == ',') addComma(i);
    }
    computed_ = sum;
    hasBlank_ = blank;
    if (checksumStatus_ == ChecksumStatus::Ok && declared_ != computed_)
        checksumStatus_ = ChecksumStatus::Bad;

    if (overflow) {
        error_ = QT_TRANSLATE_NOOP("Refusal", "too many fields");
        return false;
    }
    const std::size_t addrEnd = ncommas ? start_[0] - 1u : n;
    address_ = body_.substr(0, addrEnd);
    while (!address_.empty() && address_.back() == ' ') address_.remove_suffix(1);
    if (address_.empty()) {
        error_ = QT_TRANSLATE_NOOP("Refusal", "empty address");
        return false;
    }
    // start_[0] is the address's end: fields begin after it.
    fieldCount_ = ncommas;
    start_[ncommas] = static_cast<std::uint16_t>(n + 1);
    return true;
}

} // namespace gnss
