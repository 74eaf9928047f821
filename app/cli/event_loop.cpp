#include "cli/event_loop.h"

#include <csignal>

namespace gnss::cli {
namespace {

// How often the loop looks whether a signal asked it to stop.
constexpr int kSignalPollMs = 100;

volatile std::sig_atomic_t g_stop = 0; // the signal that asked to stop
void onSignal(int signal) {
    g_stop = signal;
}

} // namespace

EventLoop::EventLoop() {
    g_stop = 0;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QObject::connect(&signalPoll_, &QTimer::timeout, [] {
        if (g_stop) QCoreApplication::exit(128 + g_stop);
    });
    signalPoll_.start(kSignalPollMs);
}

void EventLoop::stopAfter(double seconds) {
    if (seconds > 0)
        QTimer::singleShot(static_cast<int>(seconds * 1000), &app_,
                           [] { QCoreApplication::exit(0); });
}

int EventLoop::interruptedStatus() {
    return g_stop ? 128 + g_stop : 0;
}

} // namespace gnss::cli
