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
    report(message, lost, false);
}

void Transport::abandon(const QString &why) {
    if (state_ != State::Open) return;
    fail(why, true);
    close();
}

void Transport::failRequest(const QString &message) {
    report(message, false, true);
}

void Transport::report(const QString &message, bool lost, bool request) {
    // Set before the state changes, so that whoever hears the change reads the right kind.
    error_ = message;
    errorIsRequest_ = request;
    emit errorOccurred(message);
    if (lost && state_ == State::Open) setState(State::Lost);
    if (state_ == State::Connecting) setState(State::Closed);
}

} // namespace gnss::link
