#include "connection_controller.h"

#include "core/dialect_registry.h"
#include "link/baud_detector.h"
#include "link/connection.h"
#include "link/replay_transport.h"
#include "link/serial_transport.h"
#include "link/simulator_transport.h"
#include "link/tcp_transport.h"
#include "models/receiver_session.h"

namespace gnss::app {

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
    if (!spec.valid()) {
        setState(State::Failed, tr("No source chosen"));
        return false;
    }
    if (spec.kind == SourceSpec::Kind::Serial && spec.baud == 0) {
        // Baud "auto": try the likely rates before opening for real.
        auto transport =
                std::make_unique<link::SerialTransport>(link::SerialSettings{spec.name, 9600});
        if (!transport->open()) {
            setState(State::Failed,
                     tr("Cannot open %1: %2").arg(spec.name, transport->errorString()));
            return false;
        }
        detector_ = std::make_unique<link::BaudDetector>(transport.get());
        auto *raw = transport.release();
        raw->setParent(detector_.get());
        connect(detector_.get(), &link::BaudDetector::tryingRate, this, [this](int baud) {
            setState(State::Detecting, tr("Detecting baud rate: trying %1…").arg(baud));
        });
        connect(detector_.get(), &link::BaudDetector::finished, this,
                &ConnectionController::onDetection);
        setState(State::Detecting, tr("Detecting baud rate…"));
        detector_->start();
        return true;
    }
    return openWith(spec.baud);
}

void ConnectionController::onDetection(const link::BaudDetection &result) {
    // The detector's transport is closed with it; the real connection opens at the found rate.
    detector_.release()->deleteLater();
    if (!result.found) {
        setState(State::Failed, result.error);
        return;
    }
    openWith(result.baud);
}

bool ConnectionController::openWith(int baud) {
    std::unique_ptr<link::Transport> transport;
    switch (spec_.kind) {
    case SourceSpec::Kind::Serial:
        transport = std::make_unique<link::SerialTransport>(link::SerialSettings{spec_.name, baud});
        break;
    case SourceSpec::Kind::Tcp: {
        const int colon = spec_.name.lastIndexOf(':');
        const quint16 port = quint16(spec_.name.mid(colon + 1).toUInt());
        if (colon <= 0 || port == 0) {
            setState(State::Failed, tr("TCP source must be HOST:PORT, got '%1'").arg(spec_.name));
            return false;
        }
        transport = std::make_unique<link::TcpTransport>(spec_.name.left(colon), port);
        break;
    }
    case SourceSpec::Kind::Replay:
        transport = std::make_unique<link::ReplayTransport>(spec_.name);
        break;
    case SourceSpec::Kind::Simulator:
        transport = std::make_unique<link::SimulatorTransport>(spec_.name);
        break;
    case SourceSpec::Kind::None: return false;
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
    connect(c, &link::Connection::linkLost, this, [this](const QString &why) {
        setState(State::Reconnecting, tr("Link lost: %1 — retrying every second").arg(why));
    });
    connect(c, &link::Connection::linkRestored, this,
            [this](const QString &d) { setState(State::Connected, tr("Connected: %1").arg(d)); });
    // Once the dialect is known, ask the receiver who it is (model, firmware) with its probe.
    connect(c, &link::Connection::dialectDetected, this, [this, c](const QString &id) {
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
    if (!c->open()) {
        setState(State::Failed,
                 tr("Cannot open %1: %2").arg(spec_.displayName(), c->transport()->errorString()));
        return false;
    }
    setState(State::Connected, tr("Connected: %1").arg(c->transport()->description()));
    return true;
}

void ConnectionController::disconnectFromSource() {
    if (detector_) {
        detector_->cancel();
        detector_.reset();
    }
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
