#pragma once
// TcpTransport: a receiver behind a TCP client connection (serial-to-Ethernet servers, remote
// receivers, gnss-sim --tcp). open() connects and waits up to the connect timeout.
#include "transport.h"

#include <QTcpSocket>

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
    void setConnectTimeout(int ms) { connectTimeoutMs_ = ms; }

protected:
    bool writeBytes(const QByteArray &bytes) override;

private:
    QString host_;
    quint16 port_;
    int connectTimeoutMs_ = 3000;
    QTcpSocket socket_;
    bool closing_ = false;
};

} // namespace gnss::link
