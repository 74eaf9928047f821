#pragma once
// gnss-sim --tcp on a free port of 127.0.0.1, for end-to-end tests over TCP: started, waited for
// until it prints the address it listens on, stopped at the end. REQUIRE_SIM (sim_process.h)
// takes it as it takes a SimProcess.
#include "local_port.h"
#include "sim_process.h"

namespace gnss::link::test {

class SimTcpProcess {
public:
    explicit SimTcpProcess(const QStringList &args) : port(gnss::test::closedPort()) {
        proc.start(simPath(), args + QStringList{"--tcp", QString::number(port)});
        address = firstLine(proc);
        if (!ok()) error = QString::fromLocal8Bit(proc.readAllStandardError());
    }
    ~SimTcpProcess() { stop(); }
    void stop() { stopProcess(proc); }
    // Whether it listens: it said so with the address it was given.
    bool ok() const { return port != 0 && address == QStringLiteral("127.0.0.1:%1").arg(port); }

    QProcess proc;
    quint16 port = 0;
    QString address; // "127.0.0.1:PORT", as gnss-sim printed it
    QString error;
};

} // namespace gnss::link::test
