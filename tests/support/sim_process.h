#pragma once
// gnss-sim on a pseudo-terminal, for end-to-end link tests: starts it, reads the device path it
// prints, stops it at the end. Tests QSKIP when gnss-sim is not built or lacks the dialect.
#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>

namespace gnss::link::test {

inline QString simPath() {
#ifdef GNSS_SIM_PATH
    return QStringLiteral(GNSS_SIM_PATH);
#else
    return {};
#endif
}

// The first line `proc` writes on its standard output (gnss-sim says there where it is), waited
// for up to five seconds; empty when the program did not start or ended first.
inline QString firstLine(QProcess &proc) {
    if (!proc.waitForStarted(5000)) return {};
    QElapsedTimer t;
    t.start();
    while (!proc.canReadLine() && t.elapsed() < 5000 && proc.state() == QProcess::Running)
        proc.waitForReadyRead(100);
    return QString::fromLocal8Bit(proc.readLine()).trimmed();
}

// Ends `proc`: asked first, killed after three seconds.
inline void stopProcess(QProcess &proc) {
    if (proc.state() == QProcess::NotRunning) return;
    proc.terminate();
    if (!proc.waitForFinished(3000)) proc.kill();
}

class SimProcess {
public:
    explicit SimProcess(const QStringList &args) {
        proc.setProgram(simPath());
        proc.setArguments(QStringList{"--pty"} + args);
        proc.start();
        device = firstLine(proc);
        if (!device.startsWith("/dev/")) {
            error = QString::fromLocal8Bit(proc.readAllStandardError());
            device.clear();
        }
    }
    ~SimProcess() { stop(); }
    void stop() { stopProcess(proc); }
    bool ok() const { return !device.isEmpty(); }

    QProcess proc;
    QString device;
    QString error;
};

} // namespace gnss::link::test

// Skips the test when gnss-sim is not built or `sim` (a SimProcess) did not start.
#define REQUIRE_SIM(sim)                                                                           \
    do {                                                                                           \
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");                 \
        if (!(sim).ok()) QSKIP(qPrintable("gnss-sim did not start: " + (sim).error));              \
    } while (0)
