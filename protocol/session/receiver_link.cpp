#include "session/receiver_link.h"

#include "config/settings_engine.h"
#include "core/dialect_registry.h"
#include "corrections/correction_forwarder.h"
#include "link/connection.h"
#include "link/link_opener.h"
#include "link/replay_transport.h"
#include "link/sentence_stream.h"
#include "link/vendor_detector.h"

namespace gnss::session {

namespace {
QString seconds(int ms) {
    return QString::number((ms + 500) / 1000);
}
} // namespace

ReceiverLink::ReceiverLink(const DialectRegistry &registry,
                           const link::TransportFactory &transports, QObject *parent)
    : QObject(parent), registry_(registry), transports_(transports),
      settings_(new config::SettingsEngine(this)),
      opener_(std::make_unique<link::LinkOpener>(transports, registry)) {
    stateText_ = tr("Not connected");
    connect(opener_.get(), &link::LinkOpener::tryingRate, this, [this](int baud) {
        // The rates before this one, with what was seen there.
        const int before = int(opener_->detection().tried.size()) - 1;
        const QString tried = link::LinkOpener::attemptsText(opener_->detection(), before);
        setState(State::Detecting,
                 before <= 0
                         ? tr("%1: detecting the baud rate: trying %2…").arg(spec_.name).arg(baud)
                         : tr("%1: detecting the baud rate: %2; trying %3…")
                                   .arg(spec_.name, tried)
                                   .arg(baud));
        emit detectingRate(baud);
    });
    connect(opener_.get(), &link::LinkOpener::ready, this, &ReceiverLink::onOpenerReady);
    connect(opener_.get(), &link::LinkOpener::failed, this, &ReceiverLink::onOpenerFailed);
}

ReceiverLink::~ReceiverLink() {
    disconnectFromSource();
}

void ReceiverLink::setState(State s, const QString &text) {
    state_ = s;
    stateText_ = text;
    updateForwarder();
    emit stateChanged(s, text);
}

void ReceiverLink::updateForwarder() {
    link::Connection *c = connection_.get();
    if (c == forwardedTo_ && forwarder_) return;
    forwarder_.reset();
    forwardedTo_ = c;
    // A link that takes no writes (a replayed log, a receiver behind gpsd) gets no corrections.
    if (c && c->transport()->canWrite())
        forwarder_ =
                std::make_unique<corrections::CorrectionForwarder>(c->transport(), c->commands());
}

void ReceiverLink::forwardCorrections(const QByteArray &bytes) {
    if (forwarder_) forwarder_->feed(bytes);
}

void ReceiverLink::resetCorrectionFraming() {
    if (forwarder_) forwarder_->resetFraming();
}

const corrections::ForwarderStats *ReceiverLink::forwarderStats() const {
    return forwarder_ ? &forwarder_->stats() : nullptr;
}

void ReceiverLink::attachSettings(const Dialect *dialect) {
    settings_->attach(connection_.get(), dialect);
}

bool ReceiverLink::connectTo(const SourceSpec &spec) {
    disconnectFromSource();
    spec_ = spec;
    detectedBaud_ = 0;
    detectionDetail_.clear();
    if (!spec.valid()) {
        setState(State::Failed, tr("No source chosen"));
        return false;
    }
    if (spec.kind == SourceSpec::Kind::Serial && spec.baud == 0)
        setState(State::Detecting, tr("%1: detecting the baud rate…").arg(spec.name));
    opener_->start(spec);
    return state_ != State::Failed;
}

void ReceiverLink::onOpenerFailed(const QString &why) {
    if (opener_->detection().tried.empty()) {
        setState(State::Failed, tr("Cannot open %1: %2").arg(spec_.displayName(), why));
        return;
    }
    detectionDetail_ =
            tr("Baud rate not found: %1").arg(link::LinkOpener::attemptsText(opener_->detection()));
    setState(State::Failed, tr("%1: %2").arg(spec_.name, why));
    emit detectionFinished(0);
}

void ReceiverLink::onOpenerReady() {
    if (!opener_->detection().tried.empty()) {
        detectedBaud_ = opener_->detection().baud;
        detectionDetail_ = tr("Baud rate detected: %1")
                                   .arg(link::LinkOpener::attemptsText(opener_->detection()));
        emit detectionFinished(detectedBaud_);
    }
    connection_ = opener_->takeConnection();
    link::Connection *c = connection_.get();
    emit connectionStarted(c);
    wire(c);
    // A log that cannot be replayed (an index that contradicts it) stays so: not retried.
    if (spec_.kind == SourceSpec::Kind::Replay) c->setAutoReconnect(false);
    // A receiver that hangs with its port open, or a socket left half-open, is opened again.
    if (spec_.kind == SourceSpec::Kind::Serial || spec_.kind == SourceSpec::Kind::Tcp ||
        spec_.kind == SourceSpec::Kind::Gpsd)
        c->setSilenceLimit(kSilenceLimitMs);
    if (!c->open()) {
        setState(State::Failed,
                 tr("Cannot open %1: %2").arg(spec_.displayName(), c->transport()->errorString()));
        return;
    }
    if (c->transport()->isOpen())
        setConnected(c->transport()->description());
    else
        setState(State::Connecting, spec_.kind == SourceSpec::Kind::Replay
                                            ? tr("Opening %1…").arg(spec_.displayName())
                                            : tr("Connecting to %1…").arg(spec_.displayName()));
}

void ReceiverLink::wire(link::Connection *c) {
    connect(c, &link::Connection::opened, this, [this](const QString &d) { setConnected(d); });
    connect(c, &link::Connection::openFailed, this, [this](const QString &why, int retryMs) {
        if (retryMs > 0)
            setState(State::Reconnecting,
                     tr("%1 — trying again in %2 s").arg(why, seconds(retryMs)));
        else
            setState(State::Failed, tr("Cannot open %1: %2").arg(spec_.displayName(), why));
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
    // (Not through a link that takes no commands: the refusal would only fill the status bar.)
    connect(c, &link::Connection::dialectDetected, this, [this](const QString &id) {
        if (!sendRefusal().isEmpty()) return;
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
}

void ReceiverLink::setConnected(const QString &description) {
    setState(State::Connected, detectedBaud_ > 0 ? tr("Connected: %1 (detected)").arg(description)
                                                 : tr("Connected: %1").arg(description));
    if (connection_) identify(connection_.get());
}

void ReceiverLink::setBaudCandidates(const QList<int> &rates) {
    opener_->setCandidateRates(rates);
}

QList<int> ReceiverLink::baudCandidates() const {
    return opener_->candidateRates();
}

void ReceiverLink::retryNow() {
    if (connection_) connection_->retryNow();
}

void ReceiverLink::identify(link::Connection *c) {
    // A receiver whose output names no vendor (a GeoS-5 sends only standard sentences until it
    // is asked) is asked with each dialect's probe, as gnss-cli probe does, and the link speaks
    // the dialect that answers. Not through a link that takes no commands.
    if (c->stream()->dialect() || !sendRefusal().isEmpty()) return;
    identifier_ = std::make_unique<link::VendorDetector>(c->stream());
    connect(identifier_.get(), &link::VendorDetector::finished, this,
            [this, c](const link::VendorIdentity &v) {
                if (connection_.get() != c || c->stream()->dialect() || !v.found) return;
                if (const Dialect *d = registry_.find(v.dialect.toStdString());
                    d && d->id != "nmea")
                    c->stream()->setDialect(d);
            });
    identifier_->start();
}

void ReceiverLink::disconnectFromSource() {
    identifier_.reset();
    opener_->cancel();
    if (connection_) {
        forwarder_.reset();
        forwardedTo_ = nullptr;
        connection_->close();
        connection_.reset();
        emit connectionEnded();
    }
    if (state_ != State::Disconnected) setState(State::Disconnected, tr("Not connected"));
}

bool ReceiverLink::send(const QByteArray &sentence, QString *error) {
    if (!connection_) {
        if (error) *error = tr("Not connected: nothing was sent");
        return false;
    }
    if (const QString refusal = sendRefusal(); !refusal.isEmpty()) {
        if (error) *error = refusal;
        return false;
    }
    QString why;
    const int id = connection_->commands()->enqueue(QString::fromLatin1(sentence), {}, &why);
    if (id <= 0) {
        if (error) *error = why;
        return false;
    }
    emit sentenceSent(sentence);
    return true;
}

QString ReceiverLink::sendRefusal() const {
    const link::Transport *t = connection_ ? connection_->transport() : nullptr;
    if (!t || t->canWrite()) return {};
    const QString why = t->readOnlyReason();
    return why.isEmpty() ? tr("%1 cannot take commands").arg(t->description()) : why;
}

bool ReceiverLink::startRecording(const QString &path) {
    return connection_ && connection_->startRecording(path);
}

void ReceiverLink::stopRecording() {
    if (connection_) connection_->stopRecording();
}

bool ReceiverLink::recording() const {
    return connection_ && connection_->recorder()->isOpen();
}

} // namespace gnss::session
