#pragma once
// Debian's gpsd in the foreground on 127.0.0.1 for end-to-end tests, reading one device (a
// gnss-sim pseudo-terminal): started on a free port, waited for until it answers, stopped at the
// end. Tests QSKIP when gpsd is not installed (Debian package gpsd).
//
// The flags, for gpsd 3.22 (Debian 12):
//   -N        stay in the foreground (the test owns the process and stops it);
//   -n        open and read the device at once, not only when a client asks;
//   -b        read only ("bluetooth-safe"): gpsd writes nothing to the device;
//   -p        passive: it does not try to reconfigure the receiver either;
//   -s BAUD   the line speed fixed, so gpsd does not hunt through speeds (the simulator answers
//             a wrong speed with garbage, as a real UART would);
//   -S PORT   its own port. Without -G gpsd listens on the loopback addresses only.
// systemd socket activation is used only when LISTEN_PID/LISTEN_FDS say so: they are removed
// from its environment, so it always binds its own socket and never takes one handed down.
#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

namespace gnss::link::test {

inline QString gpsdPath() {
    QString p = QStandardPaths::findExecutable("gpsd");
    if (p.isEmpty()) p = QStandardPaths::findExecutable("gpsd", {"/usr/sbin", "/sbin"});
    return p;
}

class GpsdProcess {
public:
    GpsdProcess(const QString &device, int baud) {
        if (gpsdPath().isEmpty()) {
            error = QStringLiteral("gpsd is not installed (Debian package gpsd)");
            return;
        }
        {
            QTcpServer probe; // a free port on 127.0.0.1 (released just before gpsd takes it)
            probe.listen(QHostAddress::LocalHost);
            port = probe.serverPort();
        }
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *v : {"LISTEN_PID", "LISTEN_FDS", "LISTEN_FDNAMES", "NOTIFY_SOCKET"})
            env.remove(v);
        proc.setProcessEnvironment(env);
        proc.setProcessChannelMode(QProcess::MergedChannels);
        proc.start(gpsdPath(), {"-N", "-n", "-b", "-p", "-s", QString::number(baud), "-S",
                                QString::number(port), device});
        if (!proc.waitForStarted(5000)) {
            error = QStringLiteral("gpsd did not start: %1").arg(proc.errorString());
            return;
        }
        // Ready when it accepts a connection on its port.
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 10000 && proc.state() == QProcess::Running) {
            QTcpSocket s;
            s.connectToHost(QHostAddress::LocalHost, port);
            if (s.waitForConnected(200)) {
                ready = true;
                return;
            }
            QTest::qWait(100);
        }
        error = QStringLiteral("gpsd did not listen on 127.0.0.1:%1: %2")
                        .arg(port)
                        .arg(QString::fromLocal8Bit(proc.readAll()));
    }
    ~GpsdProcess() { stop(); }
    void stop() {
        if (proc.state() == QProcess::NotRunning) return;
        proc.terminate();
        if (!proc.waitForFinished(5000)) proc.kill();
        proc.waitForFinished(2000);
    }
    bool ok() const { return ready; }
    // What gpsd printed (it logs to standard error in the foreground).
    QString output() { return QString::fromLocal8Bit(proc.readAll()); }

    QProcess proc;
    quint16 port = 0;
    bool ready = false;
    QString error;
};

} // namespace gnss::link::test
