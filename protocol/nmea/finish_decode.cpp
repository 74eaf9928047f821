#include "nmea_messages.h"

namespace gnss::nmea {

bool finishDecode(FieldReader &r, DecodeContext &ctx, const Message &m) {
    if (!r.ok()) {
        ctx.fail(r.problem());
        return false;
    }
    ctx.deliver(m);
    return true;
}

} // namespace gnss::nmea
