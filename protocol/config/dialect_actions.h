#pragma once
// The receiver-wide actions as the settings engine and its callers use them. The actions
// themselves (which a family offers, their commands, labels and effects) are data of each
// dialect record (Dialect::actions); nothing here names a vendor.
#include "core/dialect.h"

#include <string>
#include <string_view>

namespace gnss::config {

using Action = ReceiverAction;

// "$PNVGCFG,W*hh".
std::string actionSentence(const ActionDef &a);
// "save", "defaults", "cold", "warm", "hot".
inline std::string_view actionName(Action a) {
    return toString(a);
}
// The action named so on the command line; nullopt when none is.
std::optional<Action> actionNamed(std::string_view name);

} // namespace gnss::config
