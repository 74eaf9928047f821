#pragma once
// TcpTransport: a receiver behind a TCP client connection (serial-to-Ethernet servers, remote
// receivers, gnss-sim --tcp). open() starts connecting and returns at once: the transport is
// Connecting until the socket connects (Open) or fails or times out (Closed, with the reason).
// Nothing here waits, so a GUI stays responsive with an unreachable host.
#include "link/transport.h"

#include <QTcpSocket>
#include <QTimer>

namespace gnss::link {

class TcpTransport : public Transport {
    Q_OBJECT
public:
    TcpTransport(QString host, quint16 port, QObject *parent = nullptr);
    ~TcpTransport() override;

    // "host:port"; returns false when it is not one.
    static bool parseHostPort(const QString &text, QString &host, quint16 &port);

    bool open() override;
    void close() override;
    QString description() const override;
    qint64 pendingWriteBytes() const override { return socket_.bytesToWrite(); }
    // How long a connection attempt may take before it is given up.
    void setConnectTimeout(int ms) { connectTimer_.setInterval(ms); }
    // The most read from the socket at once (a chunk handed on); the rest waits in the kernel,
    // and past its buffer TCP slows the sender down.
    static constexpr qint64 kReadChunk = 256 * 1024;

protected:
    bool writeBytes(const QByteArray &bytes) override;

private:
    void abortSocket();

    QString host_;
    quint16 port_;
    QTcpSocket socket_;
    QTimer connectTimer_;
    bool closing_ = false;
};

} // namespace gnss::link
