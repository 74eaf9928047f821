#pragma once
// Test helper: a simulated receiver made by the registry's factory, as its own class (for the
// suites that look at its settings store or state past the Receiver interface).
#include "builtin/simulators.h"

#include <cstdint>
#include <memory>
#include <string_view>

namespace gnss::test {

template <class R>
std::unique_ptr<R> makeReceiverAs(std::string_view dialect, std::uint32_t seed = 1) {
    sim::SimOptions o;
    o.seed = seed;
    auto rx = sim::makeReceiver(dialect, o);
    return std::unique_ptr<R>(static_cast<R *>(rx.release()));
}

} // namespace gnss::test
