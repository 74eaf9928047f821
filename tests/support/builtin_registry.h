#pragma once
// Test helper: the built-in dialects, made once for the whole suite.
#include "dialects.h"

namespace gnss::test {

inline const DialectRegistry &builtinRegistry() {
    static const DialectRegistry r = makeBuiltinRegistry();
    return r;
}

} // namespace gnss::test
