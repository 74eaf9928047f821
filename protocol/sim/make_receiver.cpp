// The simulator's receivers come from the dialect records: each family's record makes its own.
#include "receiver.h"

namespace gnss::sim {

std::vector<std::string_view> simulatedDialects(const DialectRegistry &registry) {
    std::vector<std::string_view> ids;
    for (const Dialect *d : registry.dialects())
        if (d->makeSimulator) ids.push_back(d->id);
    return ids;
}

std::unique_ptr<Receiver> makeReceiver(const DialectRegistry &registry, std::string_view dialect,
                                       const SimOptions &options) {
    const Dialect *d = registry.find(dialect);
    return d && d->makeSimulator ? d->makeSimulator(options) : nullptr;
}

} // namespace gnss::sim
