// Receiver-wide actions per dialect, from the specs:
//   NVS (4.8 PNVGCFG, 4.3 PNVGRST): W saves the settings to flash; R erases them and restarts
//     (defaults in force; E only erases the flash copy); F cold start, W warm restart.
//   GeoStar (4.2-4.5): SAVEFL writes the almanacs and the settings in force to flash; CSTART /
//     WSTART / HSTART; no command restores the defaults.
//   Nemerix (PNMRX111): FACTORY / COLD / WARM / HOT; the VT002 has no save command.
#include "dialect_actions.h"

#include "core/sentence_builder.h"

namespace gnss::config {

namespace {

using A = Action;

constexpr ActionDef kActions[] = {
        {"nvs", A::SaveToFlash, "PNVGCFG,W", "Save to flash",
         "The settings in force are written to flash and survive a power cycle."},
        {"nvs", A::RestoreDefaults, "PNVGCFG,R", "Restore defaults",
         "The saved settings are erased and the receiver restarts with the factory defaults."},
        {"nvs", A::ColdStart, "PNVGRST,F", "Cold start",
         "The receiver restarts without almanac or ephemeris; settings are kept."},
        {"nvs", A::WarmStart, "PNVGRST,W", "Warm start",
         "The receiver restarts with its almanac; settings are kept."},

        {"geostar", A::SaveToFlash, "GPSGG,SAVEFL", "Save to flash",
         "The almanacs and the settings in force are written to flash."},
        {"geostar", A::ColdStart, "GPSGG,CSTART", "Cold start",
         "The receiver restarts without almanac or ephemeris."},
        {"geostar", A::WarmStart, "GPSGG,WSTART", "Warm start",
         "The receiver restarts with its almanac."},
        {"geostar", A::HotStart, "GPSGG,HSTART", "Hot start",
         "The receiver restarts with almanac and ephemeris."},

        {"nemerix", A::RestoreDefaults, "PNMRX111,FACTORY", "Restore defaults",
         "The receiver returns to its factory settings and restarts."},
        {"nemerix", A::ColdStart, "PNMRX111,COLD", "Cold start",
         "The receiver restarts without almanac or ephemeris."},
        {"nemerix", A::WarmStart, "PNMRX111,WARM", "Warm start",
         "The receiver restarts with its almanac."},
        {"nemerix", A::HotStart, "PNMRX111,HOT", "Hot start",
         "The receiver restarts with almanac and ephemeris."},
};

constexpr LinkSpeed kLinkSpeed[] = {
        {"nvs", "PNVGRZA,1,", "port.COM1.baud"},
        {"geostar", "GPSGG,BDR", "port.BDR"},
        {"nemerix", "PNMRX100,", "serial.baud"},
};

} // namespace

std::span<const ActionDef> actionTable() {
    return kActions;
}

const ActionDef *findAction(std::string_view dialect, Action action) {
    for (const auto &a : kActions)
        if (a.dialect == dialect && a.action == action) return &a;
    return nullptr;
}

std::string actionSentence(const ActionDef &a) {
    return buildSentence(a.body);
}

std::string_view actionName(Action a) {
    switch (a) {
    case Action::SaveToFlash: return "save";
    case Action::RestoreDefaults: return "defaults";
    case Action::ColdStart: return "cold";
    case Action::WarmStart: return "warm";
    case Action::HotStart: return "hot";
    }
    return {};
}

const LinkSpeed *linkSpeedCommand(std::string_view dialect) {
    for (const auto &l : kLinkSpeed)
        if (l.dialect == dialect) return &l;
    return nullptr;
}

} // namespace gnss::config
