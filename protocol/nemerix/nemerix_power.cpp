// PNMRX112: operating (power) mode.
//
//   $PNMRX112,m,t*hh   0 mode (0 fully active, 1 LDCM1 low duty cycle), 1 RF off time, 5..10 s
//   $PNMRX112, 1, 5*6F low power mode with 5 s off time between two fixes
#include "nemerix/nemerix_commands.h"

namespace gnss::nemerix {

const MessageType PowerMode::kType{"PNMRX112"};

bool decodePowerMode(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    PowerMode m;
    m.mode = r.integer(0, "operating mode");
    m.offPeriod = r.integer(1, "off period");
    if (!m.mode && r.ok()) r.fail(0, "operating mode", QT_TRANSLATE_NOOP("Refusal", "missing"));
    if (m.mode && (*m.mode < 0 || *m.mode > 1))
        r.fail(0, "operating mode", QT_TRANSLATE_NOOP("Refusal", "not 0 or 1"));
    if (m.offPeriod && (*m.offPeriod < 5 || *m.offPeriod > 10))
        r.fail(1, "off period", QT_TRANSLATE_NOOP("Refusal", "out of range 5..10"));
    return finishDecode(r, ctx, m);
}

void PowerMode::writeJson(JsonWriter &w) const {
    w.beginObject().field("mode", mode).key("mode_name");
    if (mode)
        w.value(*mode == 0 ? "fully active" : "LDCM1");
    else
        w.null();
    w.field("off_period_s", offPeriod).endObject();
}

EncodeResult encodePowerMode(int mode, std::optional<int> offPeriod, std::string_view prefix) {
    EncodeResult r;
    if (mode < 0 || mode > 1) {
        r.error = "power mode: " + std::to_string(mode) +
                  " is out of range; accepted: 0 (fully active) or 1 (LDCM1)";
        return r;
    }
    if (offPeriod && (*offPeriod < 5 || *offPeriod > 10)) {
        r.error =
                "off period: " + std::to_string(*offPeriod) + " is out of range; accepted: 5..10 s";
        return r;
    }
    if (mode == 1 && !offPeriod) {
        r.error = "off period: required with power mode 1 (LDCM1); accepted: 5..10 s";
        return r;
    }
    std::string fields = "," + std::to_string(mode);
    if (offPeriod) fields += "," + std::to_string(*offPeriod);
    return buildCommand("112", fields, prefix);
}

} // namespace gnss::nemerix
