#include "tcp_transport.h"

namespace gnss::link {

TcpTransport::TcpTransport(QString host, quint16 port, QObject *parent)
    : Transport(parent), host_(std::move(host)), port_(port) {
    connect(&socket_, &QTcpSocket::readyRead, this, [this] {
        const QByteArray bytes = socket_.readAll();
        if (!bytes.isEmpty()) emit bytesReceived(bytes);
    });
    connect(&socket_, &QTcpSocket::disconnected, this, [this] {
        if (closing_) return;
        fail(tr("%1: the connection was closed by the other side").arg(description()), true);
    });
    connect(&socket_, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        if (closing_ || e == QAbstractSocket::RemoteHostClosedError) return; // disconnected()
        if (state() == State::Open)
            fail(tr("%1: %2").arg(description(), socket_.errorString()), true);
    });
}

TcpTransport::~TcpTransport() {
    closing_ = true;
    socket_.abort();
}

bool TcpTransport::parseHostPort(const QString &text, QString &host, quint16 &port) {
    const int colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0) return false;
    bool ok = false;
    const uint p = text.mid(colon + 1).toUInt(&ok);
    if (!ok || p == 0 || p > 65535) return false;
    host = text.left(colon);
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    port = static_cast<quint16>(p);
    return true;
}

bool TcpTransport::open() {
    closing_ = true;
    socket_.abort();
    closing_ = false;
    socket_.connectToHost(host_, port_);
    if (!socket_.waitForConnected(connectTimeoutMs_)) {
        fail(tr("Cannot connect to %1: %2").arg(description(), socket_.errorString()), false);
        closing_ = true;
        socket_.abort();
        closing_ = false;
        return false;
    }
    setState(State::Open);
    return true;
}

void TcpTransport::close() {
    closing_ = true;
    socket_.abort();
    closing_ = false;
    setState(State::Closed);
}

bool TcpTransport::writeBytes(const QByteArray &bytes) {
    if (socket_.state() != QAbstractSocket::ConnectedState) return false;
    return socket_.write(bytes) == bytes.size();
}

QString TcpTransport::description() const {
    return QStringLiteral("%1:%2").arg(host_).arg(port_);
}

} // namespace gnss::link
