#pragma once
// RawStreamServer: a stream's bytes, exactly as they come, to every client that connects (the
// "share this receiver with other programs" case: a TCP port others read NMEA and RTCM from).
// Read-only: what clients send is read and discarded. Every client has a bounded queue
// (StreamClients): one that does not read is dropped, nobody waits for it. Binds 127.0.0.1
// unless told otherwise. Qt Core and Network; nothing blocks.
#include "serve/stream_server.h"

namespace gnss::serve {

class RawStreamServer : public StreamServer {
    Q_OBJECT
public:
    explicit RawStreamServer(QObject *parent = nullptr);

    // Stops listening and closes every client.
    void close();
    // Bytes to every client.
    void publish(const QByteArray &bytes);
    quint64 bytesIgnored() const { return ignored_; } // sent by clients

protected:
    void accepted(QTcpSocket *socket) override;

private:
    quint64 ignored_ = 0;
};

} // namespace gnss::serve
