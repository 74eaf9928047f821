// RawStreamServer: raw bytes to every client, bounded queues; see raw_stream_server.h.
#include "serve/raw_stream_server.h"

namespace gnss::serve {

RawStreamServer::RawStreamServer(QObject *parent) : StreamServer(parent) {
    connect(&clients_, &StreamClients::received, this,
            [this](quint64, const QByteArray &bytes) { ignored_ += quint64(bytes.size()); });
}

void RawStreamServer::accepted(QTcpSocket *socket) {
    const quint64 id = clients_.add(socket, false);
    if (id) clients_.start(id, QString(), QString());
}

void RawStreamServer::close() {
    stopListening();
    clients_.closeAll();
}

void RawStreamServer::publish(const QByteArray &bytes) {
    if (bytes.isEmpty()) return;
    for (quint64 id : clients_.streamingIds()) clients_.send(id, bytes);
}

} // namespace gnss::serve
