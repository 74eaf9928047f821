#pragma once
// StreamServer: what the servers of protocol/serve share: a QTcpServer (127.0.0.1 unless told
// otherwise, port 0: a free one) and its clients (StreamClients: bounded queues, slow ones
// dropped), their list and their comings and goings. NtripCaster and RawStreamServer add what
// they answer and send.
#include "serve/stream_clients.h"

#include <QHostAddress>
#include <QObject>

#include <memory>

class QTcpServer;
class QTcpSocket;

namespace gnss::serve {

class StreamServer : public QObject {
    Q_OBJECT
public:
    ~StreamServer() override;

    void setLimits(const ServeLimits &limits) { clients_.setLimits(limits); }
    // Listens on `address` (127.0.0.1 by default), `port` 0: a free one. False with
    // errorString() when it cannot.
    bool listen(const QHostAddress &address = QHostAddress(QHostAddress::LocalHost),
                quint16 port = 0);
    QString errorString() const;
    QHostAddress address() const;
    quint16 port() const;

    QList<ClientInfo> clients() const { return clients_.clients(); }
    quint64 droppedSlow() const { return clients_.droppedSlow(); }
    // Disconnects a client the user chose ("dropped by the user"); false when it is gone.
    bool dropClient(quint64 id);
    quint64 overCapacity() const { return clients_.overCapacity(); }

signals:
    void clientConnected(const gnss::serve::ClientInfo &client);
    void clientDisconnected(const gnss::serve::ClientInfo &client, const QString &why);
    void clientsChanged();
    // A connection closed at once: as many clients as allowed are already served.
    void clientTurnedAway(const gnss::serve::ClientInfo &client);

protected:
    // `accepted` is called with each new connection the server takes on.
    explicit StreamServer(QObject *parent);
    virtual void accepted(QTcpSocket *socket) = 0;
    // Stops listening (the clients are the subclass's to close).
    void stopListening();

    StreamClients clients_;

private:
    std::unique_ptr<QTcpServer> server_;
};

} // namespace gnss::serve
