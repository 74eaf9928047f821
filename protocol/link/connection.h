#pragma once
// Connection: one receiver link and everything that runs on it: the transport, the decoder, the
// command queue and (when asked) the recorder. When the link drops it says so, tries again every
// second (a serial device is looked up by its serial number, so it is found again under a new
// port name) and carries on; the recording continues into the same files with a gap mark.
#include "command_queue.h"
#include "core/stream_decoder.h"
#include "recorder.h"
#include "transport.h"

#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace gnss::link {

class Connection : public QObject {
    Q_OBJECT
public:
    using SentenceHandler = std::function<void(const SentenceEvent &)>;

    Connection(std::unique_ptr<Transport> transport, const DialectRegistry &registry,
               DecoderOptions options = {}, QObject *parent = nullptr);
    ~Connection() override;

    bool open();
    void close();

    Transport *transport() const { return transport_.get(); }
    CommandQueue *commands() { return &queue_; }
    StreamDecoder &decoder() { return decoder_; }
    Recorder *recorder() { return &recorder_; }

    // Every sentence received, decoded (or with the reason it was not).
    void setSentenceHandler(SentenceHandler handler) { handler_ = std::move(handler); }

    // Records what arrives from now on (and every command sent) to FILE + FILE.idx.
    bool startRecording(const QString &path, bool append = false);
    void stopRecording() { recorder_.close(); }

    void setReconnectInterval(int ms) { retry_.setInterval(ms); }
    void setAutoReconnect(bool on) { autoReconnect_ = on; }
    bool isReconnecting() const { return retry_.isActive(); }
    quint64 bytesReceived() const { return bytes_; }

signals:
    void linkLost(const QString &reason);
    void reconnectAttempt(int attempt);
    void linkRestored(const QString &description);
    void dialectDetected(const QString &dialectId);

private:
    void onBytes(const QByteArray &bytes);
    void onState(Transport::State s);
    void tryReconnect();

    std::unique_ptr<Transport> transport_;
    const DialectRegistry &registry_;
    StreamDecoder decoder_;
    CommandQueue queue_;
    Recorder recorder_;
    SentenceHandler handler_;
    QTimer retry_;
    bool autoReconnect_ = true;
    bool userClosed_ = true;
    int attempts_ = 0;
    quint64 bytes_ = 0;
    const Dialect *announced_ = nullptr;
};

} // namespace gnss::link
