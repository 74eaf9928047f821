#pragma once
// A TCP port on 127.0.0.1 for a test's server: free at the moment it is asked for.
#include <QHostAddress>
#include <QTcpServer>

namespace gnss::test {

// A TCP port on 127.0.0.1 with nobody listening.
inline quint16 closedPort() {
    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost);
    const quint16 port = probe.serverPort();
    probe.close();
    return port;
}

} // namespace gnss::test
