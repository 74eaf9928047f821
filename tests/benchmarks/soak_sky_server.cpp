#include "soak_sky_server.h"

#include <QDateTime>
#include <QTcpSocket>

namespace gnss::soak {

constexpr qint64 kMaxQueuedBytes = 1 << 20;

SkyServer::SkyServer(double speed) : speed_(speed) {
    QObject::connect(&server_, &QTcpServer::newConnection, [this] {
        QTcpSocket *c = server_.nextPendingConnection();
        if (client_) {
            c->close(); // one client at a time
            return;
        }
        client_ = c;
        startMs_ = QDateTime::currentMSecsSinceEpoch() - qint64(simulatedSeconds() * 1000 / speed_);
        timer_.start();
    });
    timer_.setInterval(1);
    QObject::connect(&timer_, &QTimer::timeout, [this] { fill(); });
}

bool SkyServer::listen() {
    return server_.listen(QHostAddress::LocalHost, 0);
}

void SkyServer::fill() {
    if (!client_ || client_->state() != QAbstractSocket::ConnectedState) return;
    const double due = double(QDateTime::currentMSecsSinceEpoch() - startMs_) / 1000.0 * speed_;
    const auto dueEpoch = std::int64_t(due * SoakSky::kRateHz);
    QByteArray out;
    while (epoch_ < dueEpoch && client_->bytesToWrite() + out.size() < kMaxQueuedBytes &&
           out.size() < (256 << 10))
        out += sky_.epoch(epoch_++);
    if (!out.isEmpty()) client_->write(out);
}

} // namespace gnss::soak
