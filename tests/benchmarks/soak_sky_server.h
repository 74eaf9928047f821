#pragma once
// SkyServer: SoakSky's 20 Hz, 60-satellite stream on a TCP port of 127.0.0.1, for gnss-cli
// (gnss-sim's receivers go up to 10 Hz and about 25 satellites). Simulated time runs at `speed`
// times real time, or slower when the client does not take it that fast (at most 1 MB waits
// in the socket): simulatedSeconds() is what was sent.
#include "soak_sky.h"

#include <QTcpServer>
#include <QTimer>

class QTcpSocket;

namespace gnss::soak {

class SkyServer {
public:
    explicit SkyServer(double speed);
    bool listen(); // 127.0.0.1, a free port
    int port() const { return int(server_.serverPort()); }
    double simulatedSeconds() const { return double(epoch_) / SoakSky::kRateHz; }
    std::int64_t epochs() const { return epoch_; }

private:
    void fill();

    double speed_;
    SoakSky sky_;
    QTcpServer server_;
    QTcpSocket *client_ = nullptr;
    QTimer timer_;
    qint64 startMs_ = -1;
    std::int64_t epoch_ = 0;
};

} // namespace gnss::soak
