#pragma once
// The frame of every field-reading decoder: a FieldReader over the sentence, an empty message,
// `read` filling it when the sentence has at least `required` fields, then finishDecode (the
// message delivered, or the reader's first problem reported).
#include "core/finish_decode.h"

#include <cstddef>

namespace gnss {

// Inlined: the decoders of the hot sentences (GGA, RMC, GSA, GSV) are this frame around their
// reads, as fast as when each wrote it out.
template <class M, class Read>
[[gnu::always_inline]] inline bool decodeWith(const Sentence &s, DecodeContext &ctx,
                                              std::size_t required, Read &&read) {
    FieldReader r(s);
    M m;
    if (r.require(required)) read(r, m);
    return finishDecode(r, ctx, m);
}

} // namespace gnss
