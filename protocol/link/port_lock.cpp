#include "link/port_lock.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <csignal>
#include <limits>
#include <sys/types.h>
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
    // Another user's process cannot be looked into (unless we are root), nor one hidden by
    // hidepid or ptrace limits: its list is unreadable or its links empty.
    if (device.isEmpty() || !fds.isReadable()) return std::nullopt;
    const QStringList entries =
            fds.entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
    bool unknown = entries.isEmpty();
    for (const QString &fd : entries) {
        const QString target = QFileInfo(fds.filePath(fd)).symLinkTarget();
        if (target == device) return true;
        unknown = unknown || target.isEmpty();
    }
    if (unknown) return std::nullopt;
    return false;
}

// The lock file QSerialPort would use: in the first of its folders that is readable and has
// the file or may be written (qserialport_unix.cpp); empty when that folder has none.
QString lockFilePath(const QString &name) {
    for (const char *folder : kLockFolders) {
        const QFileInfo dir{QLatin1String(folder)};
        const QFileInfo file(dir.filePath() + QLatin1Char('/') + name);
        if (!dir.isReadable()) continue;
        if (file.exists()) return file.isFile() ? file.filePath() : QString(); // not a FIFO
        if (dir.isWritable()) return {};
    }
    return {};
}

} // namespace

std::optional<PortLockHolder> portLockHolder(const QString &devicePath) {
    const QString path = lockFilePath(lockName(devicePath));
    QFile file(path);
    if (path.isEmpty() || !file.open(QIODevice::ReadOnly)) return std::nullopt;
    // QLockFile writes "PID\nprogram\nhost\n..."; lockdev and minicom "%10d\n".
    const QList<QByteArray> lines = file.read(4096).split('\n');
    bool ok = false;
    const qint64 pid = lines.value(0).trimmed().toLongLong(&ok);
    if (!ok || pid <= 0 || pid > std::numeric_limits<pid_t>::max()) return std::nullopt;
    PortLockHolder h;
    h.lockFile = file.fileName();
    h.pid = pid;
    const QString named = QString::fromLocal8Bit(lines.value(1).trimmed());
    h.alive = ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
    // (The lock's program name is not compared with the process's: QLockFile writes the
    // application's name, "GNSS Workbench" for the window, not its executable's.)
    if (h.alive) {
        h.program = processName(pid);
        h.hasPortOpen = hasOpen(pid, devicePath);
    }
    if (h.program.isEmpty()) h.program = named;
    return h;
}
#else
std::optional<PortLockHolder> portLockHolder(const QString &) {
    return std::nullopt;
}
#endif

} // namespace gnss::link
