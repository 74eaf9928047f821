#pragma once

#include <QString>

#include <optional>

namespace gnss::link {

// Who holds a serial port's lock file: the UUCP-style LCK..name file that QSerialPort (and
// minicom, picocom, lockdev) leave in the lock folder while a program has the port open. Read
// when an open fails on the lock, so that the message names the program instead of guessing.
struct PortLockHolder {
    QString lockFile;   // where the lock is, e.g. /run/lock/LCK..ttyUSB0
    qint64 pid = 0;     // the process the lock names
    QString program;    // its name (/proc/PID/comm, else the lock file's), empty when unknown
    bool alive = false; // a process with that id runs
    // Whether that process has the device open: empty when its open files cannot be read.
    std::optional<bool> hasPortOpen;
};

// The lock file of `devicePath` (an absolute path, e.g. /dev/ttyUSB0) and who it names; empty
// when there is none or it names no process. Unix only (elsewhere always empty).
std::optional<PortLockHolder> portLockHolder(const QString &devicePath);

} // namespace gnss::link
