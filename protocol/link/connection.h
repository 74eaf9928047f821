#pragma once
// Connection: one receiver link and everything that runs on it: the transport, its one decoder
// (SentenceStream: every listener subscribes there, nothing decodes the bytes again), the
// command queue and (when asked) the recorder. When the link drops, or a connection in the
// background fails, it says so and tries again after 1, 2, 4 ... 30 s (a serial device is looked
// up by its serial number, so it is found again under a new port name); nothing waits in the
// caller's thread. The recording continues into the same files with a gap mark. A link open but
// silent past its limit (setSilenceLimit) is taken as dropped.
#include "core/stream_decoder.h"
#include "link/command_queue.h"
#include "link/recorder.h"
#include "link/sentence_stream.h"
#include "link/transport.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace gnss::link {

class Connection : public QObject {
    Q_OBJECT
public:
    // `transport` may already be open (a port handed over by baud detection).
    Connection(std::unique_ptr<Transport> transport, const DialectRegistry &registry,
               DecoderOptions options = {}, QObject *parent = nullptr);
    ~Connection() override;

    // Opens the link, or starts opening it (see Transport::open): false when it failed at once.
    bool open();
    void close();

    Transport *transport() const { return transport_.get(); }
    // Every sentence received, decoded once (or with the reason it was not): subscribe here.
    SentenceStream *stream() { return &stream_; }
    StreamDecoder &decoder() { return stream_.decoder(); }
    CommandQueue *commands() { return &queue_; }
    Recorder *recorder() { return &recorder_; }

    // Records what arrives from now on (and every command sent) to FILE + FILE.idx.
    bool startRecording(const QString &path, bool append = false);
    void stopRecording() { recorder_.close(); }

    // The first wait before trying again and the longest (the wait doubles in between).
    void setReconnectDelays(int firstMs, int maxMs);
    void setAutoReconnect(bool on) { autoReconnect_ = on; }
    // An open link silent this long is taken as lost (a hung receiver, a half-open socket): it
    // is closed and opened again as after a drop, the recording marked. 0: never (the default).
    void setSilenceLimit(int ms);
    // How long the open link has been silent, in ms (0 while it is not open).
    qint64 silentMs() const;
    // Tries again now instead of at the planned time (a device was plugged in).
    void retryNow();
    bool isReconnecting() const { return retry_.isActive(); }
    // How long until the next attempt, in ms (0 when none is planned).
    int nextRetryMs() const { return retry_.isActive() ? retry_.remainingTime() : 0; }
    quint64 bytesReceived() const { return stream_.bytesReceived(); }

signals:
    // The link is up for the first time (after a connection made in the background).
    void opened(const QString &description);
    // An attempt to open (the first or a retry) failed; `retryMs` until the next (0: none).
    void openFailed(const QString &reason, int retryMs);
    void linkLost(const QString &reason, int retryMs);
    void reconnectAttempt(int attempt);
    void linkRestored(const QString &description);
    void dialectDetected(const QString &dialectId);

private:
    void onState(Transport::State s);
    void tryReconnect();
    // Plans the next attempt; returns its delay in ms (0 when none is planned).
    int scheduleRetry();

    std::unique_ptr<Transport> transport_;
    const DialectRegistry &registry_;
    SentenceStream stream_;
    CommandQueue queue_;
    Recorder recorder_;
    QTimer retry_;
    QTimer watch_; // the silence limit, checked every second
    QElapsedTimer lastByte_;
    int silenceLimitMs_ = 0;
    int firstRetryMs_ = 1000, maxRetryMs_ = 30000, nextRetryMs_ = 1000;
    bool autoReconnect_ = true;
    bool userClosed_ = true;
    bool everOpen_ = false;
    Transport::State lastState_ = Transport::State::Closed;
    int attempts_ = 0;
};

} // namespace gnss::link
