#pragma once
// The point a command measures accuracy against: --reference LAT,LON[,HEIGHT], or
// --reference-site NAME (a site of the user's list, protocol/sites) as its antenna reference
// point. Shared by summary and ttff; defined in cmd_sites.cpp.
#include "cli/cli_args.h"
#include "compare/accuracy.h"

#include <optional>

namespace gnss::cli {

// Sets `point` from whichever option is given (left empty with neither). Returns 0, or the exit
// status with the reason on standard error: 2 for a malformed point, both options, or a site that
// is unknown or ambiguous (naming the close matches); 1 when the site list cannot be read.
int referenceFromArgs(const Args &args, std::optional<compare::ReferencePoint> &point);

} // namespace gnss::cli
