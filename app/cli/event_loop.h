#pragma once
// The QCoreApplication the link commands (probe, monitor, record, send, ntrip) need, plus
// Ctrl-C/SIGTERM ending the event loop (so recordings are flushed and closed, not cut) with the
// status a shell gives a program the signal killed: 128 + its number (130 for Ctrl-C), so scripts
// can tell an interruption from an end.
#include <QCoreApplication>
#include <QTimer>

namespace gnss::cli {

class EventLoop {
public:
    EventLoop();
    // Ends the loop after `seconds` (none when <= 0).
    void stopAfter(double seconds);
    int exec() { return app_.exec(); }
    // The exit status of an interruption (128 + the signal), 0 when none came.
    static int interruptedStatus();

private:
    int argc_ = 1;
    char name_[9] = "gnss-cli";
    char *argv_[2] = {name_, nullptr};
    QCoreApplication app_{argc_, argv_};
    QTimer signalPoll_;
};

} // namespace gnss::cli
