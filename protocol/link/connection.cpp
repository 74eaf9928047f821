#include "connection.h"

namespace gnss::link {

Connection::Connection(std::unique_ptr<Transport> transport, const DialectRegistry &registry,
                       DecoderOptions options, QObject *parent)
    : QObject(parent), transport_(std::move(transport)), registry_(registry),
      decoder_(registry, std::move(options)), queue_(transport_.get()) {
    std::vector<const Dialect *> all(registry.dialects().begin(), registry.dialects().end());
    queue_.setOtherDialects(all);
    queue_.setDialect(decoder_.dialect());
    retry_.setInterval(1000);
    connect(&retry_, &QTimer::timeout, this, &Connection::tryReconnect);
    connect(transport_.get(), &Transport::bytesReceived, this, &Connection::onBytes);
    connect(transport_.get(), &Transport::stateChanged, this, &Connection::onState);
}

Connection::~Connection() {
    retry_.stop();
    recorder_.close(); // flush before the transport goes
}

bool Connection::open() {
    userClosed_ = false;
    attempts_ = 0;
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

void Connection::onBytes(const QByteArray &bytes) {
    bytes_ += static_cast<quint64>(bytes.size());
    decoder_.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                  [this](const SentenceEvent &ev) {
                      if (handler_) handler_(ev);
                  });
    if (decoder_.dialect() != announced_) {
        announced_ = decoder_.dialect();
        queue_.setDialect(announced_);
        if (announced_)
            emit dialectDetected(QString::fromUtf8(announced_->id.data(), announced_->id.size()));
    }
}

void Connection::onState(Transport::State s) {
    if (s == Transport::State::Lost) {
        decoder_.finish(); // a sentence cut by the drop is counted, not glued to the next one
        emit linkLost(transport_->errorString());
        if (autoReconnect_ && !userClosed_) {
            attempts_ = 0;
            retry_.start();
        }
    }
}

void Connection::tryReconnect() {
    if (userClosed_) return retry_.stop();
    ++attempts_;
    emit reconnectAttempt(attempts_);
    if (transport_->open()) {
        retry_.stop();
        emit linkRestored(transport_->description());
    }
}

} // namespace gnss::link
