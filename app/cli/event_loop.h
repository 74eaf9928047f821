#pragma once
// The QCoreApplication the link commands (probe, monitor, record, send, ntrip) need, plus
// Ctrl-C/SIGTERM ending the event loop (so recordings are flushed and closed, not cut) with the
// status a shell gives a program the signal killed: 128 + its number (130 for Ctrl-C), so scripts
// can tell an interruption from an end.
#include <QCoreApplication>
#include <QTimer>

#include <memory>

namespace gnss::cli {

class EventLoop {
public:
    // `withGui`: a QGuiApplication on the offscreen platform (unless QT_QPA_PLATFORM says
    // otherwise), for what paints (a PDF report), with or without a display.
    explicit EventLoop(bool withGui = false);
    ~EventLoop();
    // Ends the loop after `seconds` (none when <= 0).
    void stopAfter(double seconds);
    int exec() { return app_->exec(); }
    // The exit status of an interruption (128 + the signal), 0 when none came.
    static int interruptedStatus();

private:
    int argc_ = 1;
    char name_[9] = "gnss-cli";
    char *argv_[2] = {name_, nullptr};
    std::unique_ptr<QCoreApplication> app_;
    std::unique_ptr<QTimer> signalPoll_; // made after the application
};

} // namespace gnss::cli
