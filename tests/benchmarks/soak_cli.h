#pragma once
#include "soak_options.h"

namespace gnss::soak {
// `gnss-cli monitor` or `gnss-cli record` (o.cli) on `gnss-sim --dialect nvs --tcp` at o.speed
// and o.rateHz, sampled from /proc: returns the exit code.
int runCliSoak(const SoakOptions &o);
} // namespace gnss::soak
