#pragma once
// ReplayTransport: a recorded log played back as if it came from the receiver, at its original
// pace (the recorded host timestamps from FILE.idx, or, for a plain NMEA log, the UTC times in
// its sentences), faster or slower, paused, stepped or sought. Replays read only: write() fails.
//
// open() maps the file and times it on a worker thread (Connecting, with progress), so opening a
// big log never holds up the thread the transport lives in; it turns Open when the timeline is
// ready. Nothing of the log is copied into memory but the bytes being delivered.
#include "link/recording.h"
#include "link/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <thread>

namespace gnss::link {

class ReplayTransport : public Transport {
    Q_OBJECT
public:
    enum class Timing {
        Auto,         // host timestamps when FILE.idx exists, else sentence times
        HostTime,     // recorded host timestamps (needs the index)
        SentenceTime, // UTC times in GGA/RMC/ZDA/GNS/GLL; sentences without one go with the last
        AsFast,       // no waiting: everything at once (decoding a log)
    };
    Q_ENUM(Timing)

    explicit ReplayTransport(QString path, Timing timing = Timing::Auto, QObject *parent = nullptr);
    ~ReplayTransport() override;

    bool open() override;
    void close() override;
    QString description() const override;
    bool canWrite() const override { return false; }
    QString readOnlyReason() const override;

    // Seconds of the recording (first to last chunk) and the current position in it.
    double duration() const;
    double position() const;
    Timing timing() const { return effective_; }

    // Playback speed: 2 = twice as fast. Takes effect at once, from the current position.
    void setSpeed(double factor);
    double speed() const { return speed_; }
    void pause();
    void resume();
    bool isPaused() const { return paused_; }
    // Delivers the next group of bytes recorded at the same time (one read, or one epoch's
    // sentences), then stays paused. Returns false at the end.
    bool step();
    // Moves to `seconds` from the start: the next bytes delivered are the first recorded at or
    // after that time. Keeps the paused/playing state.
    void seek(double seconds);
    bool atEnd() const { return next_ >= timeline_.size(); }

    // Everything in the recording (for tests and for "bytes replayed == bytes recorded").
    const Recording &recording() const { return recording_; }

signals:
    // A command sent or a gap noted in the recording, reached during playback.
    void recordedEvent(const gnss::link::RecordedEvent &event);
    void finished();
    // While opening: how much of the log has been timed, 0-100.
    void openingProgress(int percent);

protected:
    bool writeBytes(const QByteArray &) override { return false; }

private:
    struct Slice {
        double t; // seconds from the start of the recording
        qint64 offset, length;
    };
    struct Loaded; // what the worker thread hands back
    // Times the recording (runs on the worker thread); false when cancelled.
    static bool buildTimeline(const Recording &recording, Timing timing, Timing &effective,
                              std::vector<Slice> &timeline, const std::atomic<bool> &cancel,
                              const std::function<void(int)> &progress);
    void pollLoader();
    void finishOpen(const std::shared_ptr<Loaded> &loaded);
    void stopLoader();
    void tick();
    void deliverUpTo(std::size_t end);
    void restartClock();

    QString path_;
    Timing timing_, effective_ = Timing::Auto;
    Recording recording_;
    std::vector<Slice> timeline_;
    std::size_t next_ = 0;      // index of the next slice to deliver
    std::size_t nextEvent_ = 0; // index of the next recorded event
    double speed_ = 1.0;
    bool paused_ = false;
    bool finishedSignalled_ = false;
    double anchorPos_ = 0; // recording time at the last (re)start of the clock
    QElapsedTimer clock_;
    QTimer timer_;
    // The worker hands its progress and result over through atomics and its own end (joined),
    // which ThreadSanitizer can follow, not through functors posted in Qt's event queue.
    QTimer loadPoll_;
    std::thread loader_;
    std::atomic<bool> cancelLoad_{false};
    std::atomic<int> loadPercent_{-1};
    std::atomic<bool> loadDone_{false};
    std::shared_ptr<Loaded> loaded_; // the worker's until loadDone_, then this thread's
    int percentShown_ = -1;
};

} // namespace gnss::link
