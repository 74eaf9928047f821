#include "link/connection.h"

namespace gnss::link {

Connection::Connection(std::unique_ptr<Transport> transport, const DialectRegistry &registry,
                       DecoderOptions options, QObject *parent)
    : QObject(parent), transport_(std::move(transport)), registry_(registry),
      stream_(transport_.get(), registry, std::move(options)), queue_(transport_.get(), &stream_) {
    std::vector<const Dialect *> all(registry.dialects().begin(), registry.dialects().end());
    queue_.setOtherDialects(all);
    queue_.setDialect(stream_.dialect());
    retry_.setSingleShot(true);
    connect(&retry_, &QTimer::timeout, this, &Connection::tryReconnect);
    connect(&stream_, &SentenceStream::dialectChanged, this, [this](const Dialect *d) {
        queue_.setDialect(d);
        if (d) emit dialectDetected(QString::fromUtf8(d->id.data(), qsizetype(d->id.size())));
    });
    connect(transport_.get(), &Transport::stateChanged, this, &Connection::onState);
    lastState_ = transport_->state();
    lastByte_.start();
    connect(transport_.get(), &Transport::bytesReceived, this, [this] { lastByte_.restart(); });
    watch_.setInterval(1000);
    connect(&watch_, &QTimer::timeout, this, [this] {
        if (silenceLimitMs_ > 0 && silentMs() >= silenceLimitMs_)
            transport_->abandon(tr("no data for %1 s").arg(silenceLimitMs_ / 1000));
    });
}

void Connection::setSilenceLimit(int ms) {
    silenceLimitMs_ = std::max(0, ms);
    if (silenceLimitMs_ > 0)
        watch_.start();
    else
        watch_.stop();
}

qint64 Connection::silentMs() const {
    return transport_->isOpen() ? lastByte_.elapsed() : 0;
}

Connection::~Connection() {
    retry_.stop();
    recorder_.close(); // flush before the transport goes
}

void Connection::setReconnectDelays(int firstMs, int maxMs) {
    firstRetryMs_ = std::max(1, firstMs);
    maxRetryMs_ = std::max(firstRetryMs_, maxMs);
    nextRetryMs_ = firstRetryMs_;
}

bool Connection::open() {
    userClosed_ = false;
    attempts_ = 0;
    nextRetryMs_ = firstRetryMs_;
    if (transport_->isOpen() || transport_->isConnecting()) {
        everOpen_ = everOpen_ || transport_->isOpen();
        return true; // handed over open, or already on its way
    }
    return transport_->open();
}

void Connection::close() {
    userClosed_ = true;
    retry_.stop();
    transport_->close();
}

bool Connection::startRecording(const QString &path, bool append) {
    if (!recorder_.open(path, transport_->description(), append)) return false;
    recorder_.attach(transport_.get());
    return true;
}

int Connection::scheduleRetry() {
    // A request the other end refused (a device it does not have) would be refused again.
    if (!autoReconnect_ || userClosed_ || transport_->errorIsRequest()) return 0;
    const int delay = nextRetryMs_;
    nextRetryMs_ = std::min(maxRetryMs_, nextRetryMs_ * 2);
    retry_.start(delay);
    return delay;
}

void Connection::onState(Transport::State s) {
    const Transport::State before = lastState_;
    lastState_ = s;
    switch (s) {
    case Transport::State::Open:
        lastByte_.restart(); // silence is counted from the opening
        retry_.stop();
        nextRetryMs_ = firstRetryMs_; // a link that came up starts the backoff afresh
        if (everOpen_) {
            emit linkRestored(transport_->description());
        } else {
            everOpen_ = true;
            emit opened(transport_->description());
        }
        break;
    case Transport::State::Lost: {
        stream_.finish(); // a sentence cut by the drop is counted, not glued to the next one
        const int delay = scheduleRetry();
        emit linkLost(transport_->errorString(), delay);
        break;
    }
    case Transport::State::Closed:
        // An opening in the background that failed (not one closed on purpose).
        if (before == Transport::State::Connecting && !userClosed_) {
            const int delay = scheduleRetry();
            emit openFailed(transport_->errorString(), delay);
        }
        break;
    case Transport::State::Connecting: break;
    }
}

void Connection::retryNow() {
    if (!retry_.isActive()) return;
    retry_.stop();
    tryReconnect();
}

void Connection::tryReconnect() {
    if (userClosed_) return;
    ++attempts_;
    emit reconnectAttempt(attempts_);
    if (!transport_->open()) {
        // Failed at once (a serial device still absent): wait longer before the next try.
        const int delay = scheduleRetry();
        emit openFailed(transport_->errorString(), delay);
    }
}

} // namespace gnss::link
