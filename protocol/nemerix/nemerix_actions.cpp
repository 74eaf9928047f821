// VT002 receiver-wide actions, presets and port speeds, as data of the dialect record.
//   PNMRX111: FACTORY / COLD / WARM / HOT; the VT002 has no save command.
//   PNMRX100: 1200 to 57600 bit/s.
#include "nemerix_actions.h"

namespace gnss::nemerix {
namespace {

using A = ReceiverAction;

constexpr ActionDef kActions[] = {
        {A::RestoreDefaults, "PNMRX111,FACTORY", "Restore defaults",
         "The receiver returns to its factory settings and restarts."},
        {A::ColdStart, "PNMRX111,COLD", "Cold start",
         "The receiver restarts without almanac or ephemeris."},
        {A::WarmStart, "PNMRX111,WARM", "Warm start", "The receiver restarts with its almanac."},
        {A::HotStart, "PNMRX111,HOT", "Hot start",
         "The receiver restarts with almanac and ephemeris."},
};

constexpr int kBauds[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600};

constexpr PresetValue kTracker[] = {
        {"rate.RMC", "1"}, {"rate.GGA", "0"}, {"rate.GLL", "0"}, {"rate.GSA", "0"},
        {"rate.GSV", "0"}, {"rate.VTG", "0"}, {"rate.ZDA", "0"}, {"nmrx.300", "0"},
        {"nmrx.301", "0"}, {"nmrx.302", "0"}, {"nmrx.303", "0"}, {"nmrx.304", "0"},
};
constexpr Preset kPresets[] = {
        {"Minimal output for trackers",
         "RMC once a second and nothing else: the least traffic for a tracker.", kTracker},
};

} // namespace

std::span<const ActionDef> actions() {
    return kActions;
}
std::span<const Preset> presets() {
    return kPresets;
}
std::span<const int> supportedBauds() {
    return kBauds;
}

} // namespace gnss::nemerix
