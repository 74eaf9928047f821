#include "corrections/correction_source.h"

namespace gnss::corrections {

CorrectionSource::CorrectionSource(QObject *parent) : QObject(parent) {
    monotonic_.start();
    retryTimer_.setSingleShot(true);
    stallTimer_.setSingleShot(true);
    connect(&retryTimer_, &QTimer::timeout, this, &CorrectionSource::onRetry);
    connect(&stallTimer_, &QTimer::timeout, this, &CorrectionSource::onStall);
    status_ = tr("Not started");
}

CorrectionSource::~CorrectionSource() = default;

void CorrectionSource::setReconnectSettings(const ntrip::ReconnectSettings &settings) {
    policy_ = ntrip::ReconnectPolicy(settings);
}

void CorrectionSource::setStallTimeout(int ms) {
    stallMs_ = std::max(ms, 0);
    if (stallMs_ == 0) stallTimer_.stop();
}

void CorrectionSource::start() {
    retryTimer_.stop();
    stallTimer_.stop();
    if (state_ != State::Idle) closeConnection();
    policy_.reset();
    error_.clear();
    failedOnRequest_ = false;
    setState(State::Connecting); // the subclass refines the status as it goes
    openConnection();
}

void CorrectionSource::stop() {
    retryTimer_.stop();
    stallTimer_.stop();
    closeConnection();
    setStatus(tr("Stopped"));
    setState(State::Idle);
}

void CorrectionSource::setState(State s) {
    if (s == state_) return;
    state_ = s;
    emit stateChanged(s);
}

void CorrectionSource::setStatus(const QString &text) {
    const QString status = redacted(text);
    if (status == status_) return;
    status_ = status;
    emit statusChanged(status);
}

void CorrectionSource::setConnecting(const QString &status) {
    setStatus(status);
    setState(State::Connecting);
    if (stallMs_ > 0) stallTimer_.start(stallMs_);
}

void CorrectionSource::setReceiving(const QString &status) {
    setStatus(status);
    setState(State::Receiving);
    if (stallMs_ > 0) stallTimer_.start(stallMs_);
}

void CorrectionSource::deliver(const QByteArray &bytes) {
    if (bytes.isEmpty() || state_ != State::Receiving) return;
    bytes_ += static_cast<quint64>(bytes.size());
    policy_.dataReceived(nowMs());
    if (stallMs_ > 0) stallTimer_.start(stallMs_);
    emit dataReceived(bytes);
}

void CorrectionSource::failed(const QString &text, bool retry) {
    if (!isActive()) return; // a second report of the same failure
    const QString message = redacted(text);
    stallTimer_.stop();
    closeConnection();
    error_ = message;
    emit errorOccurred(message);
    if (!isActive()) return; // stopped from a slot connected to errorOccurred
    if (retry && autoReconnect_) {
        const auto wait = static_cast<int>(policy_.nextDelayMs());
        retryTimer_.start(wait); // before the state changes, so retryInMs() tells it
        setStatus(tr("%1; trying again in %2 s").arg(message).arg((wait + 999) / 1000));
        setState(State::WaitingToRetry);
    } else {
        setStatus(message);
        setState(State::Failed);
    }
}

void CorrectionSource::refused(const QString &message) {
    if (!isActive()) return;
    failedOnRequest_ = true; // before the state says Failed
    failed(message, false);
}

void CorrectionSource::finished(const QString &status) {
    retryTimer_.stop();
    stallTimer_.stop();
    closeConnection();
    setStatus(status);
    setState(State::Idle);
}

QString CorrectionSource::stallText(bool receiving) const {
    const QString s = QString::number(stallMs_ / 1000.0); // "30", "0.3"
    return receiving ? tr("No data from %1 for %2 s").arg(description(), s)
                     : tr("No answer from %1 within %2 s").arg(description(), s);
}

void CorrectionSource::onStall() {
    if (!isActive()) return;
    failed(stallText(state_ == State::Receiving), true);
}

void CorrectionSource::onRetry() {
    if (state_ != State::WaitingToRetry) return;
    setState(State::Connecting);
    openConnection();
}

QString CorrectionSource::describeSocketError(QAbstractSocket::SocketError error,
                                              const QString &where, const QString &host,
                                              const QString &qtText) {
    switch (error) {
    case QAbstractSocket::ConnectionRefusedError:
        return tr("%1 refused the connection: nothing is listening on that port").arg(where);
    case QAbstractSocket::HostNotFoundError:
        return tr("Host %1 not found: check the name and the network").arg(host);
    case QAbstractSocket::SocketTimeoutError: return tr("%1 did not answer in time").arg(where);
    case QAbstractSocket::RemoteHostClosedError: return tr("%1 closed the connection").arg(where);
    case QAbstractSocket::NetworkError:
        return tr("Network error on the way to %1: %2").arg(where, qtText);
    default: return tr("Connection to %1 failed: %2").arg(where, qtText);
    }
}

} // namespace gnss::corrections
