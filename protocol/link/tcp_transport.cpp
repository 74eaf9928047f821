#include "link/tcp_transport.h"

#include "link/while_closing.h"

namespace gnss::link {

TcpTransport::TcpTransport(QString host, quint16 port, QObject *parent)
    : Transport(parent), host_(std::move(host)), port_(port) {
    connectTimer_.setSingleShot(true);
    connectTimer_.setInterval(kDefaultConnectTimeoutMs);
    // Bounded reads: when what is read is handed on more slowly than it comes (a consumer
    // blocked on a full pipe, gnss-cli monitor behind a slow reader), Qt's buffer would
    // otherwise take in all the kernel holds at once, chunks of megabytes, and the program's
    // memory would follow the longest stall (gnss-soak --cli monitor grew 15 MB in 24 hours).
    socket_.setReadBufferSize(kReadChunk);
    connect(&connectTimer_, &QTimer::timeout, this, [this] {
        if (state() != State::Connecting) return;
        abortSocket();
        fail(tr("Cannot connect to %1: no answer within %2 s")
                     .arg(description())
                     .arg(connectTimer_.interval() / 1000.0),
             false);
    });
    connect(&socket_, &QTcpSocket::connected, this, [this] {
        connectTimer_.stop();
        setState(State::Open);
    });
    connect(&socket_, &QTcpSocket::readyRead, this, [this] {
        const QByteArray bytes = socket_.readAll();
        if (!bytes.isEmpty()) emit bytesReceived(bytes);
    });
    connect(&socket_, &QTcpSocket::disconnected, this, [this] {
        if (closing_ || state() != State::Open) return;
        fail(tr("%1: the connection was closed by the other side").arg(description()), true);
    });
    connect(&socket_, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        if (closing_) return;
        if (state() == State::Connecting) {
            connectTimer_.stop();
            const QString why = socket_.errorString();
            abortSocket();
            fail(tr("Cannot connect to %1: %2").arg(description(), why), false);
            return;
        }
        if (e == QAbstractSocket::RemoteHostClosedError) return; // disconnected() says it
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

void TcpTransport::abortSocket() {
    whileClosing(closing_, [this] { socket_.abort(); });
}

bool TcpTransport::open() {
    abortSocket();
    setState(State::Connecting);
    connectTimer_.start();
    socket_.connectToHost(host_, port_); // the result arrives as connected() or errorOccurred()
    return state() != State::Closed;
}

void TcpTransport::close() {
    connectTimer_.stop();
    abortSocket();
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
