#pragma once
// A pseudo-terminal that stands for a receiver which never answers: a program opens its device as
// a serial port, and the test reads back every byte the program wrote to it (to prove that
// nothing was sent).
#include <QByteArray>
#include <QString>

#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

namespace gnss::test {

class ListeningPty {
public:
    ListeningPty() {
        master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
        device_ = QString::fromLocal8Bit(::ptsname(master_));
    }
    ~ListeningPty() {
        if (master_ >= 0) ::close(master_);
    }
    ListeningPty(const ListeningPty &) = delete;
    ListeningPty &operator=(const ListeningPty &) = delete;

    bool ok() const { return !device_.isEmpty(); }
    const QString &device() const { return device_; }
    // Everything written to the device since the last call.
    QByteArray written() {
        QByteArray all;
        char buf[4096];
        for (;;) {
            const ssize_t n = ::read(master_, buf, sizeof buf);
            if (n > 0) {
                all.append(buf, n);
                continue;
            }
            if (n < 0 && errno == EINTR) continue;
            return all; // EAGAIN (nothing more), or EIO (no one has the device open)
        }
    }

private:
    int master_ = -1;
    QString device_;
};

} // namespace gnss::test
