#pragma once
// How often the models and views refresh, whatever the receiver's rate: a 20 Hz receiver must
// not make the window repaint 20 times a second per dock.
#include <QTimer>

namespace gnss::ui {

inline constexpr int kLiveRefreshMs = 100;       // 10 Hz: what a person watches move
inline constexpr int kStatisticsRefreshMs = 250; // 4 Hz: figures read, not watched
inline constexpr int kTrendRefreshMs = 500;      // 2 Hz: charts and dumps are for trends

// Starts `timer` calling `tick` (a slot of `context`, or a function) every `intervalMs`, for as
// long as `context` lives.
template <class Context, class Tick>
void startRefreshTimer(QTimer &timer, int intervalMs, Context *context, Tick tick) {
    timer.setInterval(intervalMs);
    QObject::connect(&timer, &QTimer::timeout, context, std::move(tick));
    timer.start();
}

} // namespace gnss::ui
