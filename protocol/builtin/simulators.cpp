#include "builtin/simulators.h"

// One row per receiver family that has a simulated receiver (docs/adding-a-dialect.md).
#include "geostar/sim/geostar_sim_receiver.h"
#include "nemerix/sim/nemerix_sim_receiver.h"
#include "nmea/sim/nmea_sim_receiver.h"
#include "nvs/sim/nvs_sim_receiver.h"

namespace gnss::sim {

namespace {
std::vector<SimulatedFamily> builtinFamilies() {
    return {
            {"nvs", nvs::makeSimulatedReceiver},
            {"geostar", geostar::makeSimulatedReceiver},
            {"nemerix", nemerix::makeSimulatedReceiver},
            {"nmea", makeNmeaReceiver},
    };
}
} // namespace

const SimulatorTable &builtinSimulators() {
    static const SimulatorTable table(builtinFamilies());
    return table;
}

SimulatorTable makeSimulators(const std::vector<SimulatedFamily> &more) {
    std::vector<SimulatedFamily> all = builtinFamilies();
    all.insert(all.end() - 1, more.begin(), more.end());
    return SimulatorTable(std::move(all));
}

std::unique_ptr<Receiver> makeReceiver(std::string_view dialect, const SimOptions &options) {
    return builtinSimulators().make(dialect, options);
}

} // namespace gnss::sim
