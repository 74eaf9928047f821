#pragma once
// How the PNMRX decoders count a sentence's fields: the fixed-length forms end with empty fields,
// and the list commands (PNMRX103, 107, 110) are (id, value) pairs.
#include "core/field_reader.h"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace gnss::nemerix {

// The fields up to the last one that is not empty.
std::size_t usedFields(const FieldReader &r);

// The used fields of a list of (id, value) pairs; the sentence is refused with `none` when it
// has none, with `unpaired` when they do not come in pairs (both texts are the refusal's, given
// through QT_TRANSLATE_NOOP by the caller).
std::size_t pairedFields(FieldReader &r, const char *none, const char *unpaired);

// The (id, value) pairs of the first n fields, one item each: read(items[count++], i) with i the
// id's field, while the reader has no problem; the sentence is refused with `tooMany` once they
// do not fit.
template <class Item, std::size_t N, class Read>
void readPairs(FieldReader &r, std::size_t n, std::array<Item, N> &items, std::size_t &count,
               const char *tooMany, Read &&read) {
    for (std::size_t i = 0; r.ok() && i + 1 < n; i += 2) {
        if (count == N) {
            r.failSentence(std::string(tooMany));
            break;
        }
        read(items[count++], i);
    }
}

// Every field's text as sent, into texts[count...] (PNMRX304, PNMRX600/602: fields the spec does
// not lay out); the sentence is refused once they do not fit.
void readTexts(FieldReader &r, std::span<std::string_view> texts, std::size_t &count);

} // namespace gnss::nemerix
