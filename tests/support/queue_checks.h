#pragma once
// For the suites that drive a CommandQueue: outcomes printed by name when a QCOMPARE fails, and
// waiting for the queue's results.
#include "link/command_queue.h"

#include <QTest>

namespace gnss::link {
// QCOMPARE prints outcomes by name.
inline char *toString(CommandOutcome o) {
    return qstrdup(qPrintable(outcomeName(o)));
}

// Runs the event loop until the queue has finished `n` commands in all (false after `ms`).
inline bool waitForHistory(CommandQueue &q, int n, int ms = 5000) {
    return QTest::qWaitFor([&] { return q.history().size() >= n; }, ms);
}

} // namespace gnss::link
