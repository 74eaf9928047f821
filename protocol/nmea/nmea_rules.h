#pragma once
// The standard sentence table (GGA, RMC, GSA, GSV, ...), used by every dialect.
#include "core/dialect.h"

namespace gnss {

std::span<const SentenceRule> standardSentenceRules();

} // namespace gnss
