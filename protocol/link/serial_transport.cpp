#include "link/serial_transport.h"

#include "link/port_lock.h"

#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <vector>
#endif

namespace gnss::link {

namespace {

#ifdef Q_OS_UNIX
// Whether the user is in group `gid` in the group database: then a session that lacks it began
// before they were added (group membership is read at login).
bool userListedInGroup(gid_t gid) {
    const passwd *pw = getpwuid(geteuid());
    if (!pw) return false;
    int n = 64;
    std::vector<gid_t> groups(static_cast<std::size_t>(n));
    if (getgrouplist(pw->pw_name, pw->pw_gid, groups.data(), &n) < 0) {
        groups.resize(static_cast<std::size_t>(n));
        if (getgrouplist(pw->pw_name, pw->pw_gid, groups.data(), &n) < 0) return false;
    }
    groups.resize(static_cast<std::size_t>(n));
    for (gid_t g : groups)
        if (g == gid) return true;
    return false;
}
#endif

#ifdef Q_OS_UNIX
// Who has the port, by its lock file: a program named is one the user can end or reconfigure.
QString busyAdvice(const QString &path) {
    const std::optional<PortLockHolder> h = portLockHolder(path);
    if (!h)
        return SerialTransport::tr("Another program may have it open (a terminal program, gpsd, "
                                   "ModemManager).");
    const QString program = h->program.isEmpty() ? SerialTransport::tr("a program") : h->program;
    if (!h->alive)
        return SerialTransport::tr("Its lock file %1 is left from process %2, which has ended: "
                                   "delete that file.")
                .arg(h->lockFile)
                .arg(h->pid);
    if (h->hasPortOpen == false)
        return SerialTransport::tr("Its lock file %1 names %2 (process %3), which does not have "
                                   "it open: try again, and if it stays, end that program.")
                .arg(h->lockFile, program)
                .arg(h->pid);
    if (h->hasPortOpen == true)
        return SerialTransport::tr("%1 (process %2) has it open (lock file %3).")
                .arg(program)
                .arg(h->pid)
                .arg(h->lockFile);
    // Another user's process: its open files are not ours to see.
    return SerialTransport::tr("Its lock file %1 names %2 (process %3).")
            .arg(h->lockFile, program)
            .arg(h->pid);
}
#endif

// What to do about a port that would not open, where we can tell: QSerialPort says
// PermissionError both for a device this user may not open (EACCES) and for one another program
// holds (its lock file, EBUSY), which call for opposite advice; an access check tells them apart.
// Empty when there is nothing to add.
QString openFailureAdvice(const QString &portName, QSerialPort::SerialPortError error) {
#ifdef Q_OS_UNIX
    if (error != QSerialPort::PermissionError) return {};
    const QString path = serialDevicePath(portName);
    const QByteArray native = QFile::encodeName(path);
    // With the effective user, as open() checks (plain access() asks about the real one).
    if (::faccessat(AT_FDCWD, native.constData(), R_OK | W_OK, AT_EACCESS) == 0)
        return busyAdvice(path);
    if (errno != EACCES && errno != EPERM) return {};
    // Debian and most distributions give serial devices to the group "dialout" (crw-rw----
    // root:dialout); name the device's own group when it is the one granting access.
    QString groupName = QStringLiteral("dialout");
    struct stat st {};
    if (::stat(native.constData(), &st) == 0 && (st.st_mode & S_IRGRP) && (st.st_mode & S_IWGRP)) {
        if (const struct group *g = getgrgid(st.st_gid); g && st.st_gid != 0)
            groupName = QString::fromLocal8Bit(g->gr_name);
        if (st.st_gid != 0 && userListedInGroup(st.st_gid))
            return SerialTransport::tr("You are in the '%1' group that may use it, but this "
                                       "session began before you were added: log out and back "
                                       "in.")
                    .arg(groupName);
    }
    return SerialTransport::tr("Serial ports are for members of the '%1' group: run "
                               "`sudo usermod -aG %1 $USER`, then log out and back in.")
            .arg(groupName);
#else
    Q_UNUSED(portName);
    Q_UNUSED(error);
    return {};
#endif
}

// The listed port `p` is the one opened as `name`: "ttyUSB0", "/dev/ttyUSB0", "pts/3" or a
// /dev/serial/by-id/ link, by the rule QSerialPort opens them with.
bool samePort(const PortInfo &p, const QString &name) {
    return p.portName == name ||
           (!p.systemLocation.isEmpty() && sameSerialDevice(p.systemLocation, name));
}

} // namespace

QString serialDevicePath(const QString &portName) {
#ifdef Q_OS_UNIX
    // QSerialPort's own rule: a name that is a path (absolute, or from "./" or "../") is used
    // as it is; any other is under /dev.
    const bool path = portName.startsWith('/') || portName.startsWith(QLatin1String("./")) ||
                      portName.startsWith(QLatin1String("../"));
    return path ? portName : QStringLiteral("/dev/") + portName;
#else
    return portName;
#endif
}

bool sameSerialDevice(const QString &a, const QString &b) {
    const auto device = [](const QString &name) {
        const QString path = serialDevicePath(name);
        const QString real = QFileInfo(path).canonicalFilePath(); // by-id links, symlinks
        return real.isEmpty() ? path : real;
    };
    return device(a) == device(b);
}

SerialTransport::SerialTransport(SerialSettings settings, PortEnumerator enumerate, QObject *parent)
    : Transport(parent), settings_(std::move(settings)),
      enumerate_(enumerate ? std::move(enumerate) : PortEnumerator(systemPorts)) {
    connect(&port_, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = port_.readAll();
        if (!bytes.isEmpty()) emit bytesReceived(bytes);
    });
    connect(&port_, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

SerialTransport::~SerialTransport() {
    port_.close();
}

QString SerialTransport::resolvePortName() const {
    if (device_.serialNumber.isEmpty()) return settings_.portName;
    for (const PortInfo &p : enumerate_())
        if (p.sameDevice(device_))
            return p.systemLocation.isEmpty() ? p.portName : p.systemLocation;
    return settings_.portName;
}

bool SerialTransport::open() {
    if (port_.isOpen()) port_.close();
    ++generation_;
    const QString name = resolvePortName();
    port_.setPortName(name);
    port_.setBaudRate(settings_.baud);
    port_.setDataBits(settings_.dataBits);
    port_.setParity(settings_.parity);
    port_.setStopBits(settings_.stopBits);
    port_.setFlowControl(settings_.flowControl);
    if (!port_.open(QIODevice::ReadWrite)) {
        QString why = tr("Cannot open %1: %2").arg(name, port_.errorString());
        if (const QString advice = openFailureAdvice(name, port_.error()); !advice.isEmpty())
            why = tr("%1. %2").arg(why, advice);
        fail(why, false);
        return false;
    }
    if (name != settings_.portName) settings_.portName = name; // the device moved
    // Remember who is behind the port, to find it again under another name after an unplug.
    for (const PortInfo &p : enumerate_()) {
        if (samePort(p, name)) {
            device_ = p;
            break;
        }
    }
    if (device_.systemLocation.isEmpty()) device_.systemLocation = name;
    setState(State::Open);
    return true;
}

void SerialTransport::close() {
    port_.close();
    setState(State::Closed);
}

bool SerialTransport::writeBytes(const QByteArray &bytes) {
    if (!port_.isOpen()) return false;
    return port_.write(bytes) == bytes.size();
}

QString SerialTransport::description() const {
    return tr("%1 at %2 baud").arg(settings_.portName).arg(settings_.baud);
}

bool SerialTransport::setBaud(int baud) {
    settings_.baud = baud;
    if (!port_.isOpen()) return true;
    return port_.setBaudRate(baud);
}

void SerialTransport::discardInput() {
    if (!port_.isOpen()) return;
    port_.clear(QSerialPort::Input);
    port_.readAll();
}

void SerialTransport::onError(QSerialPort::SerialPortError error) {
    if (error == QSerialPort::NoError) return;
    const QString qtWords = port_.errorString();
    if (!port_.isOpen()) return; // open() reports its own failure
    port_.clearError();
    // A device that went away: ResourceError, or a read/write error with its node gone. A read
    // that finds nothing (the input was flushed between the notifier and the read, as a baud
    // switch does) is reported by QSerialPort as a ReadError with a stale errno: the device is
    // still there and the link is fine, so it is not a loss.
    const bool ioError = error == QSerialPort::ReadError || error == QSerialPort::WriteError ||
                         error == QSerialPort::PermissionError;
    const bool gone = error == QSerialPort::ResourceError ||
                      (ioError && !QFileInfo::exists(serialDevicePath(port_.portName())));
    if (ioError && !gone) return;
    // Qt's words for a device that went away are the system's errno ("Invalid argument" for a
    // pseudo-terminal hung up): say what happened first, keep them after it.
    const QString message =
            gone ? tr("%1: the device went away (unplugged, powered off or hung up: %2)")
                            .arg(settings_.portName, qtWords)
                 : tr("%1: %2").arg(settings_.portName, qtWords);
    if (gone) {
        // Close at once: a vanished device's file descriptor keeps signalling otherwise.
        // (Queued: not inside QSerialPort's own notifier; skipped when reopened meanwhile.)
        const int generation = generation_;
        QMetaObject::invokeMethod(
                this,
                [this, generation] {
                    if (generation == generation_) port_.close();
                },
                Qt::QueuedConnection);
    }
    fail(message, gone);
}

} // namespace gnss::link
