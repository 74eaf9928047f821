#include "corrections/tcp_correction_source.h"

#include "link/while_closing.h"

namespace gnss::corrections {

TcpCorrectionSource::TcpCorrectionSource(QString host, quint16 port, QObject *parent)
    : RawCorrectionSource(parent), host_(std::move(host)), port_(port) {
    connect(&socket_, &QTcpSocket::connected, this, [this] {
        if (!listening()) return;
        setReceiving(tr("Connected to %1, waiting for RTCM").arg(description()));
    });
    deliverReadsOf(socket_);
    connect(&socket_, &QTcpSocket::disconnected, this, [this] {
        if (!listening()) return;
        failed(tr("%1 closed the connection").arg(description()), true);
    });
    connect(&socket_, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        if (!listening() || e == QAbstractSocket::RemoteHostClosedError) return;
        failed(describeSocketError(e, description(), host_, socket_.errorString()), true);
    });
}

TcpCorrectionSource::~TcpCorrectionSource() {
    closing_ = true;
    socket_.abort();
}

QString TcpCorrectionSource::description() const {
    return (host_.contains(QLatin1Char(':')) ? QStringLiteral("[%1]:%2") : QStringLiteral("%1:%2"))
            .arg(host_)
            .arg(port_);
}

void TcpCorrectionSource::openConnection() {
    closeConnection();
    setConnecting(tr("Connecting to %1").arg(description()));
    socket_.connectToHost(host_, port_);
}

void TcpCorrectionSource::closeConnection() {
    link::whileClosing(closing_, [this] { socket_.abort(); });
}

} // namespace gnss::corrections
