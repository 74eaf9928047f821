// StreamClients: connected clients, bounded send queues, slow ones dropped.
#include "serve/stream_clients.h"

#include <algorithm>

#include <QTcpSocket>

namespace gnss::serve {

struct StreamClients::Client {
    QTcpSocket *socket = nullptr;
    ClientInfo info;
    QTimer deadline; // the request head's, then a refusal's flush
    bool closing = false;
    QString why; // when closing: the reason said when it is gone
};

StreamClients::StreamClients(QObject *parent) : QObject(parent) {
    qRegisterMetaType<gnss::serve::ClientInfo>();
    traffic_.setInterval(1000);
    connect(&traffic_, &QTimer::timeout, this, [this] {
        if (!trafficMoved_) return;
        trafficMoved_ = false;
        emit clientsChanged();
    });
    traffic_.start();
}

StreamClients::~StreamClients() {
    for (auto &[id, c] : clients_) {
        c->socket->disconnect(this);
        c->socket->abort();
    }
}

quint64 StreamClients::add(QTcpSocket *socket, bool awaitHead) {
    socket->setParent(this);
    if (int(clients_.size()) >= limits_.maxClients) {
        ++overCapacity_;
        ClientInfo away;
        away.address = socket->peerAddress();
        away.port = socket->peerPort();
        away.since = QDateTime::currentDateTimeUtc();
        emit turnedAway(away);
        socket->abort();
        socket->deleteLater();
        return 0;
    }
    const quint64 id = nextId_++;
    auto c = std::make_unique<Client>();
    c->socket = socket;
    c->info.id = id;
    c->info.address = socket->peerAddress();
    c->info.port = socket->peerPort();
    c->info.since = QDateTime::currentDateTimeUtc();
    if (limits_.socketSendBuffer > 0)
        socket->setSocketOption(QAbstractSocket::SendBufferSizeSocketOption,
                                limits_.socketSendBuffer);
    c->deadline.setSingleShot(true);
    connect(&c->deadline, &QTimer::timeout, this, [this, id] {
        const auto it = clients_.find(id);
        if (it == clients_.end()) return;
        if (it->second->closing) {
            remove(id, it->second->why);
            return;
        }
        ++headTimeouts_;
        remove(id, tr("no request within %1 s").arg(limits_.headTimeoutMs / 1000.0));
    });
    if (awaitHead) c->deadline.start(limits_.headTimeoutMs);
    connect(socket, &QTcpSocket::readyRead, this, [this, id, socket] {
        const QByteArray bytes = socket->readAll();
        const auto it = clients_.find(id);
        if (it == clients_.end() || it->second->closing) return; // read and discarded
        emit received(id, bytes);
    });
    connect(socket, &QTcpSocket::bytesWritten, this, [this, id](qint64 n) {
        const auto it = clients_.find(id);
        if (it == clients_.end()) return;
        it->second->info.bytesSent += quint64(n);
        trafficMoved_ = true;
    });
    connect(socket, &QTcpSocket::disconnected, this, [this, id] {
        const auto it = clients_.find(id);
        if (it == clients_.end()) return;
        remove(id, it->second->closing ? it->second->why : tr("closed by the client"));
    });
    clients_.emplace(id, std::move(c));
    emit connected(clients_.at(id)->info);
    emit clientsChanged();
    return id;
}

void StreamClients::start(quint64 id, const QString &user, const QString &mountpoint) {
    const auto it = clients_.find(id);
    if (it == clients_.end()) return;
    Client &c = *it->second;
    c.deadline.stop();
    c.info.user = user;
    c.info.mountpoint = mountpoint;
    c.info.streaming = true;
    emit clientsChanged();
}

void StreamClients::refuse(quint64 id, const QByteArray &reply, const QString &why) {
    const auto it = clients_.find(id);
    if (it == clients_.end()) return;
    Client &c = *it->second;
    c.closing = true;
    c.why = why;
    c.info.streaming = false;
    c.socket->write(reply);
    // A client that does not read even its refusal is not waited for long.
    c.deadline.start(limits_.headTimeoutMs);
    c.socket->disconnectFromHost(); // may emit disconnected (and remove it) at once
}

bool StreamClients::send(quint64 id, const QByteArray &bytes) {
    const auto it = clients_.find(id);
    if (it == clients_.end() || it->second->closing) return false;
    QTcpSocket *s = it->second->socket;
    const qint64 waiting = s->bytesToWrite();
    if (waiting >= limits_.queueBytes) { // full: at most the limit and one write are held
        ++droppedSlow_;
        remove(id, tr("dropped: it did not read its data (%1 KiB waiting)").arg(waiting / 1024));
        return false;
    }
    s->write(bytes);
    return true;
}

void StreamClients::closeAll(const std::function<QByteArray(const ClientInfo &)> &farewell) {
    QList<quint64> ids;
    for (const auto &[id, c] : clients_) ids << id;
    for (quint64 id : ids) {
        const auto it = clients_.find(id);
        if (it == clients_.end()) continue;
        QTcpSocket *s = it->second->socket;
        if (farewell && !it->second->closing) s->write(farewell(it->second->info));
        s->flush();
        remove(id, tr("the server stopped"));
    }
}

bool StreamClients::drop(quint64 id, const QString &why) {
    if (clients_.find(id) == clients_.end()) return false;
    remove(id, why);
    return true;
}

void StreamClients::remove(quint64 id, const QString &why) {
    const auto it = clients_.find(id);
    if (it == clients_.end()) return;
    std::unique_ptr<Client> c = std::move(it->second);
    clients_.erase(it);
    c->deadline.stop();
    c->socket->disconnect(this);
    if (c->socket->state() != QAbstractSocket::UnconnectedState) {
        // What the flush hands to the system is sent too (its bytesWritten no longer counts).
        const qint64 queued = c->socket->bytesToWrite();
        c->socket->flush();
        c->info.bytesSent += quint64(std::max<qint64>(0, queued - c->socket->bytesToWrite()));
        c->socket->disconnectFromHost();
        if (c->socket->state() != QAbstractSocket::UnconnectedState)
            c->socket->abort(); // a slow client's queue is not waited for
    }
    c->socket->deleteLater();
    emit disconnected(c->info, why);
    emit clientsChanged();
}

QList<ClientInfo> StreamClients::clients() const {
    QList<ClientInfo> out;
    for (const auto &[id, c] : clients_) out << c->info;
    return out;
}

const ClientInfo *StreamClients::find(quint64 id) const {
    const auto it = clients_.find(id);
    return it == clients_.end() ? nullptr : &it->second->info;
}

QList<quint64> StreamClients::streamingIds() const {
    QList<quint64> out;
    for (const auto &[id, c] : clients_)
        if (c->info.streaming && !c->closing) out << id;
    return out;
}

} // namespace gnss::serve
