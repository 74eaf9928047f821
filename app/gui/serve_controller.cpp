#include "gui/serve_controller.h"

#include "gui/corrections_controller.h"
#include "link/connection.h"
#include "link/transport.h"
#include "models/receiver_session.h"
#include "ntrip/ntrip_request.h"
#include "session/receiver_link.h"

namespace gnss::app {

namespace {

// A mountpoint from a receiver's name: letters, digits, '-' and '_' only.
QString mountOf(const QString &name, int index, bool corrections) {
    QString m;
    for (const QChar c : name)
        if (c.isLetterOrNumber() && c.unicode() < 128)
            m += c;
        else if (!m.isEmpty() && !m.endsWith('_'))
            m += '_';
    while (m.endsWith('_')) m.chop(1);
    if (m.isEmpty()) m = QStringLiteral("RX");
    m = m.left(24) + QString::number(index + 1);
    return corrections ? m + QStringLiteral("_CORR") : m;
}

QString endpoint(const QHostAddress &a, quint16 port) {
    return a.protocol() == QAbstractSocket::IPv6Protocol
                   ? QStringLiteral("[%1]:%2").arg(a.toString()).arg(port)
                   : QStringLiteral("%1:%2").arg(a.toString()).arg(port);
}

} // namespace

ServeController::ServeController(Receivers receivers, QObject *parent)
    : QObject(parent), receivers_(std::move(receivers)) {
    connect(&tick_, &QTimer::timeout, this, &ServeController::showClients);
    tick_.start(1000);
    refresh();
}

void ServeController::attach(ui::ServeView *view) {
    view_ = view;
    connect(view, &ui::ServeView::casterStartRequested, this,
            [this](const ui::ServeCasterRequest &r) {
                QString why;
                if (!startCaster(r, &why)) showState(), view_->setCasterState(false, why);
            });
    connect(view, &ui::ServeView::casterStopRequested, this, &ServeController::stopCaster);
    connect(view, &ui::ServeView::rawStartRequested, this,
            [this](const QString &address, int port, int receiver) {
                QString why;
                if (!startRaw(address, port, receiver, &why)) view_->setRawState(false, why);
            });
    connect(view, &ui::ServeView::rawStopRequested, this, &ServeController::stopRaw);
    connect(view, &ui::ServeView::dropClientRequested, this, &ServeController::dropClient);
    refresh();
    showState();
    showClients();
}

void ServeController::refresh() {
    streams_.clear();
    QStringList names;
    const QList<ui::ReceiverSession *> all = receivers_.all();
    for (int i = 0; i < all.size(); ++i) {
        ui::ReceiverSession *s = all[i];
        tap(s);
        names << s->name();
        streams_.append({s, false, tr("RTCM of %1").arg(s->name()),
                         mountOf(s->shortName(), i, false), s->counters().rtcmFrames > 0});
        streams_.append({s, true, tr("Corrections fed to %1").arg(s->name()),
                         mountOf(s->shortName(), i, true)});
    }
    if (!view_) return;
    QList<ui::ServeStreamChoice> choices;
    for (const Stream &st : std::as_const(streams_))
        choices.append({st.label, st.mount, st.suggested});
    view_->setStreams(choices);
    view_->setReceivers(names);
}

void ServeController::tap(ui::ReceiverSession *s) {
    if (tapped_.contains(s)) return;
    tapped_.insert(s);
    auto wire = [this, s](link::Connection *c) {
        connect(c->transport(), &link::Transport::bytesReceived, this,
                [this, s](const QByteArray &bytes) { onBytes(s, false, bytes); });
    };
    connect(s->link(), &session::ReceiverLink::connectionStarted, this, wire);
    if (s->link()->connection()) wire(s->link()->connection());
    if (CorrectionsController *c = receivers_.corrections(s))
        connect(c, &CorrectionsController::correctionsReceived, this,
                [this, s](const QByteArray &bytes) { onBytes(s, true, bytes); });
    connect(s, &QObject::destroyed, this, [this, s] { tapped_.remove(s); });
    // Named after its model once identified; offered as an RTCM source once it sends some.
    connect(s, &ui::ReceiverSession::dialectChanged, this, &ServeController::refresh);
    connect(s->feed(), &ui::ModelFeed::countersChanged, this, [this, s] {
        for (const Stream &st : std::as_const(streams_))
            if (st.session == s && !st.corrections && !st.suggested && s->counters().rtcmFrames > 0)
                return refresh();
    });
}

void ServeController::onBytes(ui::ReceiverSession *s, bool corrections, const QByteArray &bytes) {
    if (caster_)
        for (const Stream &st : std::as_const(served_))
            if (st.session == s && st.corrections == corrections) caster_->publish(st.mount, bytes);
    if (raw_ && !corrections && rawSession_ == s) raw_->publish(bytes);
}

bool ServeController::startCaster(const ui::ServeCasterRequest &r, QString *why) {
    const QHostAddress address(r.address);
    if (address.isNull()) return *why = tr("'%1' is not an IP address").arg(r.address), false;
    if (r.mounts.isEmpty()) return *why = tr("Tick a stream to serve"), false;
    if (r.user.isEmpty() != r.password.isEmpty())
        return *why = tr("Give both a user and a password, or neither"), false;
    QList<Stream> served;
    QSet<QString> names;
    for (const auto &[index, mount] : r.mounts) {
        if (index < 0 || index >= streams_.size()) continue;
        if (const std::string problem = ntrip::checkMountpoint(mount.toStdString());
            !problem.empty())
            return *why = tr("Mountpoint '%1': %2").arg(mount, QString::fromStdString(problem)),
                   false;
        if (names.contains(mount))
            return *why = tr("Mountpoint '%1' is given twice").arg(mount), false;
        names.insert(mount);
        Stream st = streams_[index];
        st.mount = mount;
        served.append(st);
    }
    stopCaster();
    auto caster = std::make_unique<serve::NtripCaster>();
    for (const Stream &st : std::as_const(served)) {
        serve::MountConfig m;
        m.name = st.mount;
        m.needsPassword = !r.user.isEmpty();
        m.describe.identifier = st.label.toStdString();
        caster->addMount(m);
    }
    if (!r.user.isEmpty()) caster->addUser(r.user, r.password);
    if (!caster->listen(address, quint16(r.port))) return *why = caster->errorString(), false;
    connect(caster.get(), &serve::StreamServer::clientsChanged, this,
            &ServeController::showClients);
    connect(caster.get(), &serve::NtripCaster::requestRefused, this,
            [this](const serve::ClientInfo &c, int status, const QString &why) {
                emit message(tr("NTRIP client %1 refused (%2): %3")
                                     .arg(endpoint(c.address, c.port))
                                     .arg(status)
                                     .arg(why));
            });
    caster_ = std::move(caster);
    served_ = served;
    showState();
    return true;
}

void ServeController::stopCaster() {
    if (caster_) caster_->close();
    caster_.reset();
    served_.clear();
    showState();
}

bool ServeController::startRaw(const QString &text, int port, int receiver, QString *why) {
    const QHostAddress address(text);
    if (address.isNull()) return *why = tr("'%1' is not an IP address").arg(text), false;
    const QList<ui::ReceiverSession *> all = receivers_.all();
    if (receiver < 0 || receiver >= all.size()) return *why = tr("No receiver to share"), false;
    stopRaw();
    auto raw = std::make_unique<serve::RawStreamServer>();
    if (!raw->listen(address, quint16(port))) return *why = raw->errorString(), false;
    connect(raw.get(), &serve::StreamServer::clientsChanged, this, &ServeController::showClients);
    raw_ = std::move(raw);
    rawSession_ = all[receiver];
    showState();
    return true;
}

void ServeController::stopRaw() {
    if (raw_) raw_->close();
    raw_.reset();
    rawSession_ = nullptr;
    showState();
}

bool ServeController::dropClient(const QString &server, quint64 id) {
    serve::StreamServer *s = nullptr;
    if (server == casterName())
        s = caster_.get();
    else if (server == rawName())
        s = raw_.get();
    if (!s) return false;
    QString who;
    for (const serve::ClientInfo &c : s->clients())
        if (c.id == id) who = endpoint(c.address, c.port);
    if (who.isEmpty() || !s->dropClient(id)) return false;
    emit message(tr("Client %1 dropped").arg(who));
    showClients();
    return true;
}

void ServeController::showState() {
    if (!view_) return;
    QStringList mounts;
    for (const Stream &st : std::as_const(served_)) mounts << st.mount;
    view_->setCasterState(caster_ != nullptr,
                          caster_ ? tr("Serving %1 on %2")
                                            .arg(mounts.join(QStringLiteral(", ")),
                                                 endpoint(caster_->address(), caster_->port()))
                                  : tr("Not serving"));
    view_->setRawState(raw_ != nullptr,
                       raw_ && rawSession_ ? tr("Sharing %1 on %2")
                                                     .arg(rawSession_->name(),
                                                          endpoint(raw_->address(), raw_->port()))
                                           : tr("Not sharing"));
}

void ServeController::showClients() {
    if (!view_) return;
    QList<QPair<QString, serve::ClientInfo>> rows;
    if (caster_)
        for (const serve::ClientInfo &c : caster_->clients()) rows.append({casterName(), c});
    if (raw_)
        for (const serve::ClientInfo &c : raw_->clients()) rows.append({rawName(), c});
    view_->setClients(rows);
}

} // namespace gnss::app
