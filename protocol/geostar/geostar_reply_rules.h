#pragma once
// How the GeoS-5 answers each command of section 4 (one rule per concrete command, derived from
// the command table so the two cannot disagree).
#include "core/dialect.h"

#include <span>

namespace gnss::geostar {

std::span<const ReplyRule> replyRules();

} // namespace gnss::geostar
