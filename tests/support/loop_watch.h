#pragma once
// Test helper: watches the event loop while it lives: the longest gap between the ticks of a
// 10 ms timer (a loop kept busy shows as a long gap), and how many ticks there were.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <algorithm>

namespace gnss::test {

struct LoopWatch {
    QTimer timer;
    QElapsedTimer clock;
    qint64 last = 0, worst = 0;
    int ticks = 0;
    LoopWatch() {
        timer.setInterval(10);
        QObject::connect(&timer, &QTimer::timeout, [this] {
            const qint64 now = clock.elapsed();
            worst = std::max(worst, now - last);
            last = now;
            ++ticks;
        });
        clock.start();
        timer.start();
    }
};

} // namespace gnss::test
