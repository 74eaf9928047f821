#include "corrections/correction_forwarder.h"

#include "link/command_queue.h"
#include "link/transport.h"
#include "rtcm/rtcm_framer.h"

namespace {
// A frame is written once the port holds less than this much not yet sent: one largest frame.
constexpr qint64 kMaxBacklogBytes = 1029;
// How often to look again while the port's buffer empties (a 1 KB frame takes 0.1 s at 115200).
constexpr int kDrainPollMs = 20;
} // namespace

namespace gnss::corrections {

class CorrectionForwarder::Framing {
public:
    rtcm::RtcmFramer framer;
};

CorrectionForwarder::CorrectionForwarder(link::Transport *transport, link::CommandQueue *queue,
                                         QObject *parent)
    : QObject(parent), transport_(transport), commands_(queue),
      framing_(std::make_unique<Framing>()) {
    if (transport)
        connect(transport, &link::Transport::stateChanged, this, [this](link::Transport::State s) {
            if (s == link::Transport::State::Open) flush();
        });
    if (queue) connect(queue, &link::CommandQueue::idle, this, &CorrectionForwarder::flush);
    drain_.setSingleShot(true);
    drain_.setInterval(kDrainPollMs);
    connect(&drain_, &QTimer::timeout, this, &CorrectionForwarder::flush);
}

CorrectionForwarder::~CorrectionForwarder() = default;

bool CorrectionForwarder::linkReady() const {
    return transport_ && transport_->isOpen() && !(commands_ && commands_->isBusy()) &&
           transport_->pendingWriteBytes() < kMaxBacklogBytes;
}

void CorrectionForwarder::feed(const QByteArray &bytes) {
    stats_.bytesIn += std::uint64_t(bytes.size());
    rtcm::RtcmFramer &framer = framing_->framer;
    framer.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
                [this](const rtcm::RtcmFrame &f) {
                    ++stats_.framesIn;
                    push(QByteArray(reinterpret_cast<const char *>(f.bytes.data()),
                                    qsizetype(f.bytes.size())));
                });
    stats_.bytesSkipped = framer.stats().bytesSkipped;
    stats_.crcFailures = framer.stats().crcFailures;
    flush();
    emit statsChanged();
}

void CorrectionForwarder::resetFraming() {
    framing_->framer.reset();
}

void CorrectionForwarder::push(QByteArray frame) {
    queuedBytes_ += int(frame.size());
    queue_.push_back(std::move(frame));
    while (queuedBytes_ > limitBytes_ && queue_.size() > 1) {
        ++stats_.framesDropped;
        stats_.bytesDropped += std::uint64_t(queue_.front().size());
        queuedBytes_ -= int(queue_.front().size());
        queue_.pop_front();
    }
}

void CorrectionForwarder::flush() {
    bool changed = false;
    while (!queue_.empty() && linkReady()) {
        QByteArray frame = std::move(queue_.front());
        queue_.pop_front();
        queuedBytes_ -= int(frame.size());
        changed = true;
        if (transport_->write(frame)) {
            ++stats_.framesForwarded;
            stats_.bytesForwarded += std::uint64_t(frame.size());
        } else {
            ++stats_.writeFailures;
            ++stats_.framesDropped;
            stats_.bytesDropped += std::uint64_t(frame.size());
        }
    }
    // Held back by the port's own buffer only: look again shortly (idle and open call too).
    if (!queue_.empty() && transport_ && transport_->isOpen() &&
        !(commands_ && commands_->isBusy()))
        drain_.start();
    if (changed) emit statsChanged();
}

} // namespace gnss::corrections
