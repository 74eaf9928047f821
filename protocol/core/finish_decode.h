#pragma once
// The step every field-reading decoder ends with: deliver the message, or report the reader's
// first problem (the field and what it holds) and deliver nothing.
#include "core/dialect.h"
#include "core/field_reader.h"

namespace gnss {

inline bool finishDecode(FieldReader &r, DecodeContext &ctx, const Message &m) {
    if (!r.ok()) {
        ctx.fail(r.problem());
        return false;
    }
    ctx.deliver(m);
    return true;
}

} // namespace gnss
