#pragma once
// Which sentence answers each NVS command, how success is told from refusal, how long to wait.
#include "core/dialect.h"

#include <span>

namespace gnss::nvs {

std::span<const ReplyRule> replyRules();

} // namespace gnss::nvs
