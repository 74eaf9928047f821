// 4.9 PNVGPPS: time pulse settings (command and reply). Empty command fields stay unchanged;
// the receiver answers every command with the resulting settings.
//
//   $PNVGPPS,a,a,a,x,xxxx,a,xxxx*hh      $PNVGPPS,P,S,U,1,1000,D,0*62
//            0 type (P software, A hardware), 1 mode (I interval, S 1PPS),
//            2 reference (U UTC, S UTC(SU), G GLONASS, N GPS), 3 timescale adjustment (1/0),
//            4 duration (1-1000 us), 5 validity control (E/D), 6 cable delay (ns)
#include "nvs/nvs_encode_util.h"

#include "core/field_table.h"

namespace gnss::nvs {

const MessageType Pps::kType{"PNVGPPS"};

const FieldRow<Pps> Pps::kFields[] = {
        {&Pps::type, "type", "type"},
        {&Pps::mode, "mode", "mode"},
        {&Pps::reference, "reference", "reference"},
        {&Pps::adjust, "timescale adjustment", "adjust"},
        {&Pps::duration, "duration", "duration"},
        {&Pps::validity, "validity control", "validity"},
        {&Pps::cableDelay, "cable delay", "cable_delay"},
};

EncodeResult encodePps(const PpsSettings &p) {
    std::string fields[7];
    auto letter = [](std::optional<char> c) { return c ? std::string(1, *c) : std::string(); };
    auto number = [](std::optional<int> v) { return v ? std::to_string(*v) : std::string(); };
    fields[0] = letter(p.type);
    fields[1] = letter(p.mode);
    fields[2] = letter(p.reference);
    fields[3] = number(p.adjust);
    fields[4] = number(p.duration);
    fields[5] = letter(p.validity);
    fields[6] = number(p.cableDelay);
    static constexpr std::string_view kKeys[7] = {"pps.type",       "pps.mode",     "pps.reference",
                                                  "pps.adjust",     "pps.duration", "pps.validity",
                                                  "pps.cable_delay"};
    std::string body = "PNVGPPS";
    for (int i = 0; i < 7; ++i) {
        if (!fields[i].empty())
            if (auto err = checkSetting(kKeys[i], fields[i]); !err.empty()) return refuse(err);
        body += "," + fields[i];
    }
    return built(body);
}

} // namespace gnss::nvs
