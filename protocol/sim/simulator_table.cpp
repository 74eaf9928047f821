#include "sim/simulator_table.h"

#include <algorithm>

namespace gnss::sim {

SimulatorTable::SimulatorTable(std::vector<SimulatedFamily> families)
    : families_(std::move(families)) {}

std::unique_ptr<Receiver> SimulatorTable::make(std::string_view dialect,
                                               const SimOptions &options) const {
    for (const SimulatedFamily &f : families_)
        if (f.dialect == dialect && f.make) return f.make(options);
    return nullptr;
}

bool SimulatorTable::has(std::string_view dialect) const {
    return std::any_of(families_.begin(), families_.end(),
                       [dialect](const SimulatedFamily &f) { return f.dialect == dialect; });
}

std::vector<std::string_view> SimulatorTable::dialects() const {
    std::vector<std::string_view> ids;
    ids.reserve(families_.size());
    for (const SimulatedFamily &f : families_) ids.push_back(f.dialect);
    return ids;
}

} // namespace gnss::sim
