// The NVS sentence table: one row per proprietary address (whole-address rules). Standard
// sentences (GGA, RMC, GSA, GSV, VTG, ZDA, HDT, the Q query) come from the standard table.
#include "nvs/nvs_messages.h"

namespace gnss::nvs {

namespace {
constexpr auto W = AddressMatch::Whole;
constexpr SentenceRule kRules[] = {
        {"PNVGVER", W, decodeVer, "Receiver and firmware information (request and reply)"},
        {"PNVGNME", W, decodeNme, "NMEA communication parameters (command and reply)"},
        {"PNVGRST", W, decodeRst, "Force receiver reset (command)"},
        {"PNVGRZA", W, decodeRza, "COM port setting (command and reply)"},
        {"PNVGRZB", W, decodeRzb, "Extended query: output message list (command)"},
        {"PNVGBSS", W, decodeBss, "Base station statistics"},
        {"PNVGTST", W, decodeTst, "Test results"},
        {"PNVGCFG", W, decodeCfg, "Save/erase settings (command and confirmation)"},
        {"PNVGPPS", W, decodePps, "Time pulse settings (command and reply)"},
        {"PNVGIMU", W, decodeImu, "Attitude and NED acceleration from IMU"},
        {"PNVGBRS", W, decodeBrs, "Base-to-rover relative position and status"},
        {"PNVGBLS", W, decodeBls, "Base-line state and heading"},
        {"PNVGVOG", W, decodeVog, "Velocity over ground"},
        {"PNVGRTK", W, decodeRtk, "RTK engine parameters (set, query and reply)"},
        {"PNVGIDL", W, decodeIdl, "Known base stations list (commands and replies)"},
        {"PNVGTME", W, decodeTme, "TOW time of time mark event"},
        {"PNVGTMU", W, decodeTmu, "UTC time of time mark event"},
        {"PNVGTMC", W, decodeTmc, "Fix data at time mark event"},
        {"PNVGSDP", W, decodeSdp, "Standard deviation of position"},
        {"PNVGSDV", W, decodeSdv, "Standard deviation of velocity"},
        {"PNVGSDH", W, decodeSdh, "Standard deviation of heading"},
        {"PNVGDOP", W, decodeDop, "DOPs of the calculated position"},
};
} // namespace

std::span<const SentenceRule> sentenceRules() {
    return kRules;
}

} // namespace gnss::nvs
