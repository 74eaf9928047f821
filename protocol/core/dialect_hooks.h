#pragma once
// The signatures of the functions a dialect record names (core/dialect.h), written once, so that
// a receiver family's folder declares each of its own in one line:
//
//     namespace gnss::geostar {
//     UpdateStateHook updateState;            // defined in geostar_state.cpp
//     }
//
// (A function type declares a function of that signature; the definition is written out.)
#include "core/dialect.h"

#include <vector>

namespace gnss {

// Dialect::updateState: the vendor-neutral receiver state from one of the dialect's messages.
using UpdateStateHook = bool(const Message &m, ReceiverState &state);
// Dialect::extractSettings: the setting values a decoded reply or command carries.
using ExtractSettingsHook = void(const Message &reply, std::vector<KeyValue> &out);

} // namespace gnss
