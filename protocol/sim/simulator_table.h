#pragma once
// SimulatorTable: the simulated receiver families a program can play, by dialect id. It sits
// beside the dialect registry (a record knows no simulator): the built-in table is
// protocol/builtin/simulators.h; a program or a test adds a family with one row.
//
//     const sim::SimulatorTable &table = sim::builtinSimulators();
//     auto rx = table.make("nvs", options); // nullptr: no simulator of that id
#include "sim/receiver.h"

#include <memory>
#include <string_view>
#include <vector>

namespace gnss::sim {

// A family's simulated receiver, made with the options given.
using MakeReceiver = std::unique_ptr<Receiver> (*)(const SimOptions &options);

struct SimulatedFamily {
    std::string_view dialect; // the dialect record's id
    MakeReceiver make;
};

class SimulatorTable {
public:
    explicit SimulatorTable(std::vector<SimulatedFamily> families);

    // The simulated receiver of `dialect`; nullptr when the table has none of that id.
    std::unique_ptr<Receiver> make(std::string_view dialect, const SimOptions &options = {}) const;
    bool has(std::string_view dialect) const;
    // The ids, in table order (for source lists, option checks and help texts).
    std::vector<std::string_view> dialects() const;

private:
    std::vector<SimulatedFamily> families_;
};

} // namespace gnss::sim
