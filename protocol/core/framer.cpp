#include "core/framer.h"

#include <array>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gnss {
namespace {

enum ByteClass : std::uint8_t { kText = 0, kStart = 1, kEnd = 2, kInvalid = 3 };

constexpr std::array<std::uint8_t, 256> makeClassTable() {
    std::array<std::uint8_t, 256> t{};
    for (int c = 0; c < 256; ++c) {
        if (c == '$' || c == '!')
            t[c] = kStart;
        else if (c == '\r' || c == '\n')
            t[c] = kEnd;
        else if (c == '\t' || (c >= 0x20 && c < 0x7F))
            t[c] = kText;
        else
            t[c] = kInvalid;
    }
    return t;
}
constexpr auto kClass = makeClassTable();

// Index of the first byte in [from, to) that is not plain sentence text, or `to`.
inline std::size_t scanText(const char *p, std::size_t from, std::size_t to) {
    std::size_t i = from;
#if defined(__SSE2__)
    const __m128i dollar = _mm_set1_epi8('$');
    const __m128i bang = _mm_set1_epi8('!');
    const __m128i space = _mm_set1_epi8(0x20);
    const __m128i del = _mm_set1_epi8(0x7F);
    const __m128i tab = _mm_set1_epi8('\t');
    while (i + 16 <= to) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i *>(p + i));
        // Signed compare: bytes 0x80-0xFF are negative, so "< 0x20" also catches 8-bit bytes.
        __m128i special = _mm_or_si128(_mm_cmpeq_epi8(v, dollar), _mm_cmpeq_epi8(v, bang));
        const __m128i ctrl = _mm_andnot_si128(_mm_cmpeq_epi8(v, tab), _mm_cmplt_epi8(v, space));
        special = _mm_or_si128(special, _mm_or_si128(ctrl, _mm_cmpeq_epi8(v, del)));
        const int mask = _mm_movemask_epi8(special);
        if (mask != 0)
            return i + static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(mask)));
        i += 16;
    }
#endif
    while (i < to && kClass[static_cast<unsigned char>(p[i])] == kText) ++i;
    return i;
}

} // namespace

void Framer::abandon(std::size_t bytes) {
    stats_.bytesSkipped += bytes;
    pending_.clear();
    inSentence_ = false;
}

void Framer::feed(std::string_view chunk, const SentenceCallback &onSentence) {
    const char *p = chunk.data();
    const std::size_t n = chunk.size();
    stats_.bytesIn += n;
    std::size_t i = 0;

    while (i < n) {
        if (pendingCr_) {
            pendingCr_ = false;
            if (p[i] == '\n') { // second half of a CR LF terminator
                ++i;
                continue;
            }
        }
        if (!inSentence_) {
            // Between sentences: skip to the next '$' or '!'.
            std::size_t j = i;
            while (j < n && kClass[static_cast<unsigned char>(p[j])] != kStart) ++j;
            stats_.bytesSkipped += j - i;
            if (j == n) return;
            inSentence_ = true;
            pending_.clear();
            i = j;
            // The start byte itself is scanned as part of the sentence below.
            const std::size_t lim = std::min(n, i + 1 + kMaxLine);
            const std::size_t k = scanText(p, i + 1, lim);
            if (k < n && k < lim) {
                const auto cls = kClass[static_cast<unsigned char>(p[k])];
                if (cls == kEnd) { // whole sentence inside this chunk: emit without copying
                    ++stats_.sentences;
                    inSentence_ = false;
                    pendingCr_ = p[k] == '\r';
                    onSentence(std::string_view(p + i, k - i));
                    i = k + 1;
                    continue;
                }
            }
            // Otherwise fall through to the general in-sentence handling from i + 1.
            pending_.push_back(p[i]);
            ++i;
            continue;
        }

        // Inside a sentence whose first pending_.size() bytes were in earlier chunks (or earlier
        // in this one). Scan no further than the length limit allows.
        const std::size_t room = kMaxLine + 1 - std::min(pending_.size(), kMaxLine + 1);
        const std::size_t lim = std::min(n, i + room);
        const std::size_t k = scanText(p, i, lim);
        if (k == lim && k < n) {
            // Reached the length limit without a terminator: drop and resynchronise.
            ++stats_.tooLong;
            abandon(pending_.size() + (k - i));
            i = k;
            continue;
        }
        if (k == n) {
            if (pending_.size() + (n - i) > kMaxLine) {
                ++stats_.tooLong;
                abandon(pending_.size() + (n - i));
                return;
            }
            pending_.append(p + i, n - i);
            return;
        }
        const auto cls = kClass[static_cast<unsigned char>(p[k])];
        pending_.append(p + i, k - i);
        if (cls == kEnd) {
            if (pending_.size() > kMaxLine) {
                ++stats_.tooLong;
                abandon(pending_.size());
            } else {
                ++stats_.sentences;
                inSentence_ = false;
                onSentence(std::string_view(pending_));
                pending_.clear();
            }
            pendingCr_ = p[k] == '\r';
            i = k + 1;
        } else if (cls == kStart) {
            ++stats_.truncated;
            abandon(pending_.size());
            i = k; // the new sentence starts here
        } else {   // a byte that no sentence contains: this was binary data, not a sentence
            ++stats_.binaryAborted;
            abandon(pending_.size() + 1);
            i = k + 1;
        }
    }
}

void Framer::finish() {
    if (inSentence_) {
        ++stats_.truncated;
        abandon(pending_.size());
    }
    pendingCr_ = false;
}

void Framer::reset() {
    pending_.clear();
    inSentence_ = false;
    pendingCr_ = false;
}

} // namespace gnss
