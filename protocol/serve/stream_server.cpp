// StreamServer: the listening socket and the clients the servers share.
#include "serve/stream_server.h"

#include <QTcpServer>
#include <QTcpSocket>

namespace gnss::serve {

StreamServer::StreamServer(QObject *parent)
    : QObject(parent), clients_(this), server_(std::make_unique<QTcpServer>()) {
    connect(server_.get(), &QTcpServer::newConnection, this, [this] {
        while (QTcpSocket *s = server_->nextPendingConnection()) accepted(s);
    });
    connect(&clients_, &StreamClients::connected, this, &StreamServer::clientConnected);
    connect(&clients_, &StreamClients::disconnected, this, &StreamServer::clientDisconnected);
    connect(&clients_, &StreamClients::clientsChanged, this, &StreamServer::clientsChanged);
    connect(&clients_, &StreamClients::turnedAway, this, &StreamServer::clientTurnedAway);
}

StreamServer::~StreamServer() = default;

bool StreamServer::listen(const QHostAddress &address, quint16 port) {
    return server_->listen(address, port);
}

QString StreamServer::errorString() const {
    return server_->errorString();
}

QHostAddress StreamServer::address() const {
    return server_->serverAddress();
}

quint16 StreamServer::port() const {
    return server_->serverPort();
}

bool StreamServer::dropClient(quint64 id) {
    return clients_.drop(id, tr("dropped by the user"));
}

void StreamServer::stopListening() {
    server_->close();
}

} // namespace gnss::serve
