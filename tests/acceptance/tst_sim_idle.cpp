// gnss-sim on a pseudo-terminal that nobody has open waits (under 5 % of a core over five
// seconds, measured from /proc), and still starts talking when a program opens the device.
#include "sim_process.h"

#include <QFile>
#include <QTest>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace {

// User + system CPU time of a process, in clock ticks (fields 14 and 15 of /proc/PID/stat).
qint64 cpuTicks(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly)) return -1;
    const QByteArray stat = f.readAll();
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    return fields.size() > 12 ? fields[11].toLongLong() + fields[12].toLongLong() : -1;
}

} // namespace

class TstSimIdle : public QObject {
    Q_OBJECT
private slots:
    void anIdleSimulatorWaitsAndStillAnswersWhenOpened() {
        gnss::link::test::SimProcess sim({"--dialect", "nmea"});
        if (!sim.ok()) QSKIP(qPrintable("gnss-sim: " + sim.error));
        QTest::qWait(500); // past start-up
        const qint64 pid = sim.proc.processId();
        const qint64 before = cpuTicks(pid);
        QVERIFY(before >= 0);
        QTest::qWait(5000);
        const qint64 used = cpuTicks(pid) - before;
        const double share = double(used) / double(sysconf(_SC_CLK_TCK)) / 5.0;
        qInfo("idle gnss-sim --pty: %.1f %% of a core over 5 s", share * 100);
        QVERIFY2(share < 0.05, qPrintable(QString::number(share * 100, 'f', 1) + " %"));

        // A program opens the device: the receiver's output flows at once.
        const int fd = ::open(sim.device.toLocal8Bit().constData(), O_RDWR | O_NOCTTY);
        QVERIFY(fd >= 0);
        termios t{};
        tcgetattr(fd, &t);
        cfmakeraw(&t);
        cfsetispeed(&t, B9600);
        cfsetospeed(&t, B9600);
        tcsetattr(fd, TCSANOW, &t);
        fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
        QByteArray got;
        QElapsedTimer clock;
        clock.start();
        while (!got.contains("GGA,") && clock.elapsed() < 5000) {
            char buf[512];
            const ssize_t n = ::read(fd, buf, sizeof buf);
            if (n > 0) got.append(buf, n);
            QTest::qWait(20);
        }
        ::close(fd);
        QVERIFY2(got.contains("GGA,"), got.left(200).constData());
    }
};

QTEST_GUILESS_MAIN(TstSimIdle)
#include "tst_sim_idle.moc"
