#pragma once
// Test helper: sentences → ReceiverState through the real decoder and StateTracker.
#include "builtin/dialects.h"
#include "core/stream_decoder.h"
#include "state/state_tracker.h"

#include <string>
#include <vector>

namespace gnss::test {

inline ReceiverState trackState(const std::vector<std::string> &lines, int *epochs = nullptr) {
    static const DialectRegistry reg = makeBuiltinRegistry();
    StreamDecoder dec(reg);
    StateTracker tracker;
    int n = 0;
    auto onEpoch = [&](const ReceiverState &) { ++n; };
    for (const auto &l : lines) {
        dec.feed(l + "\r\n", [&](const SentenceEvent &ev) {
            if (!ev.message) return;
            tracker.setDialect(dec.dialect());
            tracker.add(ev.sentence, *ev.message, ev.dialect, onEpoch);
        });
    }
    tracker.flush(onEpoch);
    if (epochs) *epochs = n;
    return tracker.state();
}

} // namespace gnss::test
