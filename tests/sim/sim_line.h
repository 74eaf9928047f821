#pragma once
// gnss-sim on either kind of line a fault suite runs its rows over (a data column "line"):
// "pty", a pseudo-terminal reached by a stable --link name (as udev gives a USB receiver, so a
// reconnect finds the new one), or "tcp", a port of 127.0.0.1 (a receiver behind a
// serial-to-Ethernet server, which drops its client and listens again). transport() makes a
// new transport to it. REQUIRE_SIM (sim_process.h) takes it as it takes a SimProcess.
#include "sim_process.h"
#include "sim_tcp_process.h"

#include "link/serial_transport.h"
#include "link/tcp_transport.h"

#include <QTemporaryDir>

#include <memory>
#include <optional>

namespace gnss::link::test {

class SimLine {
public:
    SimLine(const QString &line, const QStringList &args) {
        if (line == QLatin1String("tcp")) {
            tcp_.emplace(args);
            error = tcp_->error;
        } else {
            pty_.emplace(args + QStringList{"--link", link()});
            error = pty_->error;
        }
    }
    bool ok() const { return tcp_ ? tcp_->ok() : pty_->ok(); }
    QProcess &proc() { return tcp_ ? tcp_->proc : pty_->proc; }
    // A transport to the simulator: its TCP port, or its link at `baud`.
    std::unique_ptr<Transport> transport(int baud) const {
        if (tcp_) return std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), tcp_->port);
        return std::make_unique<SerialTransport>(SerialSettings{link(), baud});
    }
    QString error;

private:
    QString link() const { return dir_.filePath(QStringLiteral("ttyGNSS")); }

    QTemporaryDir dir_; // first: the pseudo-terminal's link is in it
    std::optional<SimTcpProcess> tcp_;
    std::optional<SimProcess> pty_;
};

} // namespace gnss::link::test
