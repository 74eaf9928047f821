#pragma once
// CorrectionForwarder: RTCM corrections into the receiver through its own link.
//
// Whatever a CorrectionSource delivers (chunks cut anywhere: a TCP segment, an HTTP chunk) is
// framed first (rtcm::RtcmFramer) and only whole frames with a good CRC are written, each in
// one write: a command of the command queue can never land inside a frame, nor a frame inside
// a command. While a command waits for its reply (the receiver must answer it undisturbed, and
// a baud switch may be under way) or the link is down, frames wait in a bounded queue; when it
// is full the oldest are dropped and counted. The same when the line is slower than the stream:
// a frame goes out only once the port's own buffer holds less than one frame, so corrections
// never pile up out of sight (growing old) in front of the next command. Nothing here blocks.
#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <cstdint>
#include <deque>
#include <memory>

namespace gnss::link {
class Transport;
class CommandQueue;
} // namespace gnss::link

namespace gnss::corrections {

struct ForwarderStats {
    std::uint64_t bytesIn = 0;         // bytes given by the source
    std::uint64_t framesIn = 0;        // whole frames with a good CRC found in them
    std::uint64_t framesForwarded = 0; // frames written to the receiver
    std::uint64_t bytesForwarded = 0;
    std::uint64_t framesDropped = 0; // the oldest, when the queue was full
    std::uint64_t bytesDropped = 0;
    std::uint64_t bytesSkipped = 0; // bytes outside any good frame (noise, HTTP remains)
    std::uint64_t crcFailures = 0;
    std::uint64_t writeFailures = 0; // frames the transport refused (counted as dropped too)
};

class CorrectionForwarder : public QObject {
    Q_OBJECT
public:
    // 16 KiB: several seconds of a typical MSM4 stream (about 1-2 KB/s); older corrections are
    // of little use to a rover anyway.
    static constexpr int kDefaultQueueBytes = 16 * 1024;

    // `queue` may be null (no command queue on this link).
    CorrectionForwarder(link::Transport *transport, link::CommandQueue *queue,
                        QObject *parent = nullptr);
    ~CorrectionForwarder() override;

    void setQueueLimit(int bytes) { limitBytes_ = bytes > 0 ? bytes : kDefaultQueueBytes; }
    int queueLimit() const { return limitBytes_; }
    // Bytes of frames waiting for the link.
    int queuedBytes() const { return queuedBytes_; }
    int queuedFrames() const { return int(queue_.size()); }
    const ForwarderStats &stats() const { return stats_; }

    // RTCM bytes from a correction source, cut anywhere.
    void feed(const QByteArray &bytes);
    // The source reconnected: a frame begun before the break will not be completed.
    void resetFraming();
    // Writes what waits, when the link can take it now (also called on idle and on open).
    void flush();

signals:
    // After every change of the counts (feed, write, drop).
    void statsChanged();

private:
    bool linkReady() const;
    void push(QByteArray frame);

    QPointer<link::Transport> transport_;
    QPointer<link::CommandQueue> commands_;
    std::deque<QByteArray> queue_;
    int queuedBytes_ = 0;
    int limitBytes_ = kDefaultQueueBytes;
    ForwarderStats stats_;
    class Framing;
    std::unique_ptr<Framing> framing_; // rtcm::RtcmFramer, kept out of this header
    QTimer drain_;                     // looks again while the port's buffer empties
};

} // namespace gnss::corrections
