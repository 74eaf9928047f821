#include "link/transport.h"

namespace gnss::link {

Transport::Transport(QObject *parent) : QObject(parent) {}

Transport::~Transport() = default;

bool Transport::write(const QByteArray &bytes) {
    if (state_ != State::Open || !writeBytes(bytes)) return false;
    emit bytesSent(bytes);
    return true;
}

bool Transport::setBaud(int) {
    return false;
}

void Transport::setState(State s) {
    if (s == state_) return;
    state_ = s;
    emit stateChanged(s);
}

void Transport::fail(const QString &message, bool lost) {
    error_ = message;
    emit errorOccurred(message);
    if (lost && state_ == State::Open) setState(State::Lost);
    if (state_ == State::Connecting) setState(State::Closed);
}

} // namespace gnss::link
