#pragma once
// The one line that registers the test-only family beside the built-in ones.
#include "acme_dialect.h"
#include "dialects.h"

namespace gnss::acme {

inline DialectRegistry registryWithAcme() {
    return makeRegistry({&dialect()});
}

} // namespace gnss::acme
