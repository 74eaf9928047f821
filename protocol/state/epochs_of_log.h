#pragma once
// epochsOfLog: a log, or a range of one (logview::LogView::slice), decoded front to back into
// epochs, for whatever needs every epoch in full rather than the index's summary of it (the
// signal history, accuracy against a reference point).
#include "core/function_ref.h"

#include <atomic>
#include <string_view>

namespace gnss {

struct Dialect;
struct Epoch;
class DialectRegistry;

// Calls `onEpoch` for each epoch. `dialect`: the one in force where the bytes begin (nullptr:
// recognised as it goes). Returns false when `cancel` turned true (checked every megabyte).
bool epochsOfLog(std::string_view log, const DialectRegistry &registry, const Dialect *dialect,
                 FunctionRef<void(const Epoch &)> onEpoch,
                 const std::atomic<bool> *cancel = nullptr);

} // namespace gnss
