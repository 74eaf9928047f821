#include "cli/event_loop.h"

#include <QGuiApplication>

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

EventLoop::EventLoop(bool withGui) {
    if (withGui) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
        app_ = std::make_unique<QGuiApplication>(argc_, argv_);
    } else {
        app_ = std::make_unique<QCoreApplication>(argc_, argv_);
    }
    signalPoll_ = std::make_unique<QTimer>();
    g_stop = 0;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QObject::connect(signalPoll_.get(), &QTimer::timeout, [] {
        if (g_stop) QCoreApplication::exit(128 + g_stop);
    });
    signalPoll_->start(kSignalPollMs);
}

EventLoop::~EventLoop() {
    signalPoll_.reset(); // before the application
}

void EventLoop::stopAfter(double seconds) {
    if (seconds > 0)
        QTimer::singleShot(static_cast<int>(seconds * 1000), app_.get(),
                           [] { QCoreApplication::exit(0); });
}

int EventLoop::interruptedStatus() {
    return g_stop ? 128 + g_stop : 0;
}

} // namespace gnss::cli
