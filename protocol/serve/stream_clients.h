#pragma once
// StreamClients: the connected clients of a server that streams (the NTRIP caster, the raw
// stream server), each with a bounded send queue.
//
// What a client is sent waits in its socket's buffer (QTcpSocket::bytesToWrite). When that
// has reached the queue limit, the next write drops the client (aborted, counted as slow) rather
// than waited for: a client that stops reading never slows the others nor the publisher, and the
// server never holds more than the limit per client. Nothing here blocks.
//
// A client may first have to send a request head (awaitHead): it is dropped when that does not
// come within the head timeout. Whatever a client sends is handed on (received) or discarded.
#include <QDateTime>
#include <QHostAddress>
#include <QObject>
#include <QTimer>

#include <map>
#include <memory>

class QTcpSocket;

namespace gnss::serve {

struct ServeLimits {
    qint64 queueBytes = 1 << 20; // a client's send queue; over it the client is dropped
    int headTimeoutMs = 5000;    // a request head must be complete within this
    int maxClients = 256;        // connections beyond this are closed at once
    int socketSendBuffer = 0;    // SO_SNDBUF for client sockets (0: the system's)
};

struct ClientInfo {
    quint64 id = 0;
    QHostAddress address;
    quint16 port = 0;
    QString user;       // empty: none given (or not asked)
    QString mountpoint; // empty: the raw stream, or before the request
    QDateTime since;    // connected at (UTC)
    quint64 bytesSent = 0;
    bool streaming = false; // being sent the stream (not just connected)
};

class StreamClients : public QObject {
    Q_OBJECT
public:
    explicit StreamClients(QObject *parent = nullptr);
    ~StreamClients() override;

    void setLimits(const ServeLimits &limits) { limits_ = limits; }
    const ServeLimits &limits() const { return limits_; }

    // Takes `socket` on (its parent becomes this); 0 when over maxClients (it is closed).
    // `awaitHead`: the head timeout runs until started() or refuse().
    quint64 add(QTcpSocket *socket, bool awaitHead);
    // The client is sent the stream from now on.
    void start(quint64 id, const QString &user, const QString &mountpoint);
    // Sends `reply` and closes the client (a refusal, a source table).
    void refuse(quint64 id, const QByteArray &reply, const QString &why);
    // Queues `bytes` for the client; false when that dropped it (its queue overflowed).
    bool send(quint64 id, const QByteArray &bytes);
    // Closes the client at once (what it was sent is flushed, the rest dropped), `why` in the
    // disconnected signal; false when there is no such client.
    bool drop(quint64 id, const QString &why);
    // Closes every client, after `farewell(id)` (may be empty) is queued.
    void closeAll(const std::function<QByteArray(const ClientInfo &)> &farewell = {});

    QList<ClientInfo> clients() const;
    const ClientInfo *find(quint64 id) const;
    QList<quint64> streamingIds() const;
    quint64 droppedSlow() const { return droppedSlow_; }
    quint64 headTimeouts() const { return headTimeouts_; }
    quint64 overCapacity() const { return overCapacity_; }

signals:
    void connected(const gnss::serve::ClientInfo &client);
    // Gone, and why in words ("closed by the client", "dropped: ...").
    void disconnected(const gnss::serve::ClientInfo &client, const QString &why);
    // Bytes sent by a client (its request, a GGA): for the server to read or ignore.
    void received(quint64 id, const QByteArray &bytes);
    // The list changed: a client came, started, left, or (at most once a second) bytes moved.
    void clientsChanged();
    // A connection closed at once: the list already holds the most clients allowed.
    void turnedAway(const gnss::serve::ClientInfo &client);

private:
    struct Client;
    void remove(quint64 id, const QString &why);

    ServeLimits limits_;
    std::map<quint64, std::unique_ptr<Client>> clients_;
    quint64 nextId_ = 1;
    quint64 droppedSlow_ = 0, headTimeouts_ = 0, overCapacity_ = 0;
    QTimer traffic_; // emits clientsChanged when bytes moved
    bool trafficMoved_ = false;
};

} // namespace gnss::serve

Q_DECLARE_METATYPE(gnss::serve::ClientInfo)
