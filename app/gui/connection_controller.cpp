#include "connection_controller.h"

#include "core/dialect_registry.h"
#include "link/baud_detector.h"
#include "link/connection.h"
#include "link/replay_transport.h"
#include "link/serial_transport.h"
#include "link/simulator_transport.h"
#include "link/tcp_transport.h"
#include "models/receiver_session.h"

#include <QStringList>

namespace gnss::app {

namespace {
QString seconds(int ms) {
    return QString::number((ms + 500) / 1000);
}
} // namespace

ConnectionController::ConnectionController(const DialectRegistry &registry,
                                           ui::ReceiverSession *session, QObject *parent)
    : QObject(parent), registry_(registry), session_(session) {
    stateText_ = tr("Not connected");
}

ConnectionController::~ConnectionController() {
    disconnectFromSource();
}

void ConnectionController::setState(State s, const QString &text) {
    state_ = s;
    stateText_ = text;
    emit stateChanged(s, text);
}

bool ConnectionController::connectTo(const SourceSpec &spec) {
    disconnectFromSource();
    spec_ = spec;
    detectedBaud_ = 0;
    detectionDetail_.clear();
    if (!spec.valid()) {
        setState(State::Failed, tr("No source chosen"));
        return false;
    }
    if (spec.kind == SourceSpec::Kind::Serial && spec.baud == 0) return detectBaud();
    return openWith(makeTransport(spec.baud));
}

bool ConnectionController::detectBaud() {
    // Baud "auto": the port is opened once; the detector tries the likely rates on it and hands
    // it over, open, at the rate it found (no close and reopen, which a lock could refuse).
    auto transport = std::make_unique<link::SerialTransport>(
            link::SerialSettings{spec_.name, link::BaudDetector::likelyRates(0).front()});
    if (!transport->open()) {
        setState(State::Failed, tr("Cannot open %1: %2").arg(spec_.name, transport->errorString()));
        return false;
    }
    detecting_ = std::move(transport);
    detector_ = std::make_unique<link::BaudDetector>(detecting_.get());
    connect(detector_.get(), &link::BaudDetector::tryingRate, this, [this](int baud) {
        QStringList tried;
        for (const auto &a : detector_->result().tried)
            if (a.baud != baud) tried << attemptText(a);
        setState(State::Detecting,
                 tried.isEmpty()
                         ? tr("%1: detecting the baud rate: trying %2…").arg(spec_.name).arg(baud)
                         : tr("%1: detecting the baud rate: %2; trying %3…")
                                   .arg(spec_.name, tried.join(QStringLiteral(", ")))
                                   .arg(baud));
        emit detectingRate(baud);
    });
    connect(detector_.get(), &link::BaudDetector::finished, this,
            &ConnectionController::onDetection);
    setState(State::Detecting, tr("%1: detecting the baud rate…").arg(spec_.name));
    detector_->start();
    return true;
}

QString ConnectionController::attemptText(const link::BaudAttempt &a) {
    if (a.validSentences > 0) return tr("%1 (valid NMEA)").arg(a.baud);
    if (a.bytes == 0) return tr("%1 (no data)").arg(a.baud);
    return tr("%1 (data, no valid sentence)").arg(a.baud);
}

void ConnectionController::onDetection(const link::BaudDetection &result) {
    // The detector is done with the port (deleted later: this runs inside its signal).
    detector_.release()->deleteLater();
    std::unique_ptr<link::Transport> port = std::move(detecting_);
    if (!result.found) {
        QStringList tried;
        for (const auto &a : result.tried) tried << attemptText(a);
        detectionDetail_ = tr("Baud rate not found: %1").arg(tried.join(QStringLiteral(", ")));
        port->close();
        port.release()->deleteLater();
        setState(State::Failed, tr("%1: %2").arg(spec_.name, result.error));
        emit detectionFinished(0);
        return;
    }
    detectedBaud_ = result.baud;
    QStringList tried;
    for (const auto &a : result.tried) tried << attemptText(a);
    detectionDetail_ = tr("Baud rate detected: %1").arg(tried.join(QStringLiteral(", ")));
    emit detectionFinished(result.baud);
    openWith(std::move(port));
}

std::unique_ptr<link::Transport> ConnectionController::makeTransport(int baud) {
    switch (spec_.kind) {
    case SourceSpec::Kind::Serial:
        return std::make_unique<link::SerialTransport>(link::SerialSettings{spec_.name, baud});
    case SourceSpec::Kind::Tcp: {
        QString host;
        quint16 port = 0;
        if (!link::TcpTransport::parseHostPort(spec_.name, host, port)) return nullptr;
        return std::make_unique<link::TcpTransport>(host, port);
    }
    case SourceSpec::Kind::Replay: return std::make_unique<link::ReplayTransport>(spec_.name);
    case SourceSpec::Kind::Simulator: return std::make_unique<link::SimulatorTransport>(spec_.name);
    case SourceSpec::Kind::None: break;
    }
    return nullptr;
}

bool ConnectionController::openWith(std::unique_ptr<link::Transport> transport) {
    if (!transport) {
        setState(State::Failed,
                 spec_.kind == SourceSpec::Kind::Tcp
                         ? tr("TCP source must be HOST:PORT, got '%1'").arg(spec_.name)
                         : tr("Cannot open %1").arg(spec_.displayName()));
        return false;
    }
    DecoderOptions options;
    if (spec_.kind == SourceSpec::Kind::Simulator) options.dialect = spec_.name.toStdString();
    session_->reset(options);
    connection_ = std::make_unique<link::Connection>(std::move(transport), registry_, options);
    link::Connection *c = connection_.get();
    session_->setCounterSource(&c->decoder());
    connect(c->transport(), &link::Transport::bytesReceived, session_,
            &ui::ReceiverSession::noteBytes);
    c->setSentenceHandler(
            [this, c](const SentenceEvent &ev) { session_->consume(ev, c->decoder().dialect()); });
    connect(c, &link::Connection::opened, this, [this](const QString &d) { setConnected(d); });
    connect(c, &link::Connection::openFailed, this, [this](const QString &why, int retryMs) {
        setState(State::Reconnecting,
                 retryMs > 0 ? tr("%1 — trying again in %2 s").arg(why, seconds(retryMs)) : why);
    });
    connect(c, &link::Connection::linkLost, this, [this](const QString &why, int retryMs) {
        setState(State::Reconnecting,
                 tr("Link lost: %1 — trying again in %2 s").arg(why, seconds(retryMs)));
    });
    connect(c, &link::Connection::reconnectAttempt, this, [this, c](int attempt) {
        setState(State::Reconnecting, tr("Reconnecting to %1 (attempt %2)…")
                                              .arg(c->transport()->description())
                                              .arg(attempt));
    });
    connect(c, &link::Connection::linkRestored, this,
            [this](const QString &d) { setConnected(d); });
    // Once the dialect is known, ask the receiver who it is (model, firmware) with its probe.
    connect(c, &link::Connection::dialectDetected, this, [this](const QString &id) {
        if (const Dialect *d = registry_.find(id.toStdString()); d && !d->probeCommand.empty())
            send(QByteArray(d->probeCommand.data(), qsizetype(d->probeCommand.size())));
    });
    connect(c->commands(), &link::CommandQueue::commandFinished, this,
            [this](const link::CommandResult &r) {
                const bool ok = r.outcome == link::CommandOutcome::Accepted ||
                                r.outcome == link::CommandOutcome::Sent;
                emit commandFinished(
                        tr("%1: %2").arg(r.sentence, r.detail.isEmpty()
                                                             ? link::outcomeName(r.outcome)
                                                             : r.detail),
                        ok);
            });
    if (auto *replay = qobject_cast<link::ReplayTransport *>(c->transport()))
        connect(replay, &link::ReplayTransport::openingProgress, this, [this](int percent) {
            if (state_ == State::Connecting)
                setState(State::Connecting,
                         tr("Opening %1… %2%").arg(spec_.displayName()).arg(percent));
        });
    if (!c->open()) {
        setState(State::Failed,
                 tr("Cannot open %1: %2").arg(spec_.displayName(), c->transport()->errorString()));
        return false;
    }
    if (c->transport()->isOpen())
        setConnected(c->transport()->description());
    else
        setState(State::Connecting, spec_.kind == SourceSpec::Kind::Replay
                                            ? tr("Opening %1…").arg(spec_.displayName())
                                            : tr("Connecting to %1…").arg(spec_.displayName()));
    return true;
}

void ConnectionController::setConnected(const QString &description) {
    setState(State::Connected, detectedBaud_ > 0 ? tr("Connected: %1 (detected)").arg(description)
                                                 : tr("Connected: %1").arg(description));
}

void ConnectionController::retryNow() {
    if (connection_) connection_->retryNow();
}

void ConnectionController::disconnectFromSource() {
    if (detector_) {
        detector_->disconnect(this); // cancelled on purpose: not a failure to report
        detector_->cancel();
        detector_.reset();
    }
    detecting_.reset();
    if (connection_) {
        connection_->close();
        connection_.reset();
        session_->setCounterSource(nullptr);
    }
    if (state_ != State::Disconnected) setState(State::Disconnected, tr("Not connected"));
}

bool ConnectionController::send(const QByteArray &sentence, QString *error) {
    if (!connection_) {
        if (error) *error = tr("Not connected: nothing was sent");
        return false;
    }
    QString why;
    const int id = connection_->commands()->enqueue(QString::fromLatin1(sentence), {}, &why);
    if (id <= 0) {
        if (error) *error = why;
        return false;
    }
    session_->noteSent(sentence);
    return true;
}

bool ConnectionController::startRecording(const QString &path) {
    return connection_ && connection_->startRecording(path);
}

void ConnectionController::stopRecording() {
    if (connection_) connection_->stopRecording();
}

bool ConnectionController::recording() const {
    return connection_ && connection_->recorder()->isOpen();
}

} // namespace gnss::app
