#include "link/port_lock.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <csignal>
#endif

namespace gnss::link {

#ifdef Q_OS_UNIX
namespace {

// The folders QSerialPort looks in for lock files, in its order (qserialport_unix.cpp).
const char *const kLockFolders[] = {"/var/lock",         "/etc/locks", "/var/spool/locks",
                                    "/var/spool/uucp",   "/tmp",       "/var/tmp",
                                    "/var/lock/lockdev", "/run/lock"};

// LCK..ttyUSB0 for /dev/ttyUSB0, LCK..pts_3 for /dev/pts/3, as QSerialPort names them.
QString lockName(const QString &devicePath) {
    QString name = devicePath.startsWith(QLatin1String("/dev/")) ? devicePath.mid(5) : devicePath;
    name.replace(QLatin1Char('/'), QLatin1Char('_'));
    return QStringLiteral("LCK..") + name;
}

QString processName(qint64 pid) {
    QFile comm(QStringLiteral("/proc/%1/comm").arg(pid));
    if (!comm.open(QIODevice::ReadOnly)) return {};
    return QString::fromLocal8Bit(comm.readAll().trimmed());
}

std::optional<bool> hasOpen(qint64 pid, const QString &devicePath) {
    const QString device = QFileInfo(devicePath).canonicalFilePath();
    const QDir fds(QStringLiteral("/proc/%1/fd").arg(pid));
    // Another user's process cannot be looked into (unless we are root).
    if (device.isEmpty() || !fds.isReadable()) return std::nullopt;
    for (const QString &fd : fds.entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot))
        if (QFileInfo(fds.filePath(fd)).symLinkTarget() == device) return true;
    return false;
}

} // namespace

std::optional<PortLockHolder> portLockHolder(const QString &devicePath) {
    const QString name = lockName(devicePath);
    for (const char *folder : kLockFolders) {
        QFile file(QLatin1String(folder) + QLatin1Char('/') + name);
        if (!file.exists()) continue;
        if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
        // QLockFile writes "PID\nprogram\nhost\n..."; lockdev and minicom "%10d\n".
        const QList<QByteArray> lines = file.read(4096).split('\n');
        bool ok = false;
        const qint64 pid = lines.value(0).trimmed().toLongLong(&ok);
        if (!ok || pid <= 0) return std::nullopt;
        PortLockHolder h;
        h.lockFile = file.fileName();
        h.pid = pid;
        h.alive = ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
        if (h.alive) {
            h.program = processName(pid);
            h.hasPortOpen = hasOpen(pid, devicePath);
        }
        if (h.program.isEmpty()) h.program = QString::fromLocal8Bit(lines.value(1).trimmed());
        return h;
    }
    return std::nullopt;
}
#else
std::optional<PortLockHolder> portLockHolder(const QString &) {
    return std::nullopt;
}
#endif

} // namespace gnss::link
