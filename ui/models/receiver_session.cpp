#include "models/receiver_session.h"

#include "config/settings_engine.h"
#include "link/connection.h"
#include "link/sentence_stream.h"
#include "session/receiver_link.h"

namespace gnss::ui {

ReceiverSession::ReceiverSession(const DialectRegistry &registry,
                                 const link::TransportFactory &transports, QObject *parent)
    : QObject(parent), models_{new ReceiverStateModel(this), new SatelliteModel(this),
                               new MessageStatsModel(this), new ConsoleModel(this)},
      feed_(new ModelFeed(registry, models_, this)),
      link_(new session::ReceiverLink(registry, transports, this)) {
    history_ = new SignalHistoryModel(models_.state, this);
    // A new connection: the models start over and count what its decoder counts; its bytes and
    // sentences reach them.
    connect(link_, &session::ReceiverLink::connectionStarted, this, [this](link::Connection *c) {
        feed_->reset();
        feed_->setCounterSource(&c->decoder());
        connect(c->transport(), &link::Transport::bytesReceived, feed_, &ModelFeed::noteBytes);
        connect(c->stream(), &link::SentenceStream::sentenceDecoded, feed_,
                [this, c](const SentenceEvent &ev) { feed_->consume(ev, c->stream()->dialect()); });
    });
    connect(link_, &session::ReceiverLink::connectionEnded, feed_,
            [this] { feed_->setCounterSource(nullptr); });
    connect(link_, &session::ReceiverLink::sentenceSent, feed_, &ModelFeed::noteSent);
    // The settings engine follows the connection and the dialect it speaks.
    connect(feed_, &ModelFeed::dialectChanged, this, [this](const Dialect *d) {
        link_->attachSettings(d);
        emit dialectChanged(d);
    });
    connect(link_, &session::ReceiverLink::stateChanged, this,
            [this] { link_->attachSettings(feed_->dialect()); });
}

ReceiverSession::~ReceiverSession() {
    // Closing the link fails a command still waiting for its answer and ends the connection:
    // neither may reach this half-destroyed session.
    link_->disconnect(this);
    link_->disconnect(feed_);
    link_->disconnectFromSource();
}

QString ReceiverSession::shortName() const {
    if (!givenName_.isEmpty()) return givenName_;
    // What it was last known as on this source, while a reconnection finds it again: the name
    // (and the file a recording gets) does not flicker to "Receiver".
    const QString source = link_->source().toString();
    QString known;
    const ReceiverIdentity &id = models_.state->state().identity;
    if (!id.model.empty())
        known = QString::fromStdString(id.model);
    else if (const Dialect *d = dialect())
        known = QString::fromLatin1(d->displayName.data(), qsizetype(d->displayName.size()));
    if (!known.isEmpty()) {
        // A model outranks the dialect's name it was known by before.
        if (id.model.empty() && knownSource_ == source && !knownName_.isEmpty() && knownFromModel_)
            return knownName_;
        knownName_ = known;
        knownSource_ = source;
        knownFromModel_ = !id.model.empty();
        return known;
    }
    if (knownSource_ == source && !knownName_.isEmpty()) return knownName_;
    return tr("Receiver");
}

QString ReceiverSession::name() const {
    if (!givenName_.isEmpty()) return givenName_;
    const QString place = link_->source().place();
    return place.isEmpty() ? shortName() : tr("%1 %2").arg(shortName(), place);
}

void ReceiverSession::setGivenName(const QString &name) {
    givenName_ = name.trimmed();
}

} // namespace gnss::ui
