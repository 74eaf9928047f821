#pragma once
// Test helper: the built-in dialects, made once for the whole suite (and the built-in simulated
// receivers: sim::builtinSimulators()).
#include "builtin/dialects.h"
#include "builtin/simulators.h"

namespace gnss::test {

inline const DialectRegistry &builtinRegistry() {
    static const DialectRegistry r = makeBuiltinRegistry();
    return r;
}

} // namespace gnss::test
