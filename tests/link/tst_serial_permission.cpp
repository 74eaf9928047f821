// A serial port refused for permission says why and what to do (join the dialout group, log out
// and in), in the message SerialTransport gives: the GUI's status bar and gnss-cli both show it.
// A port that is busy gets no such advice: its lock file names the program that holds it. An
// absent one gets none at all.
//
// The device is a pseudo-terminal made unopenable (chmod 000). Root opens anything whatever its
// mode, so when the tests run as root the opening is done as the user "nobody": in this process
// by switching the effective user for the moment of the open (seteuid, then back), and gnss-cli
// is started as nobody.
#include "link/serial_transport.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

using gnss::link::SerialSettings;
using gnss::link::SerialTransport;

namespace {

uid_t nobodyUid() {
    const passwd *pw = getpwnam("nobody");
    return pw ? pw->pw_uid : 65534;
}

gid_t nobodyGid() {
    const passwd *pw = getpwnam("nobody");
    return pw ? pw->pw_gid : 65534;
}

// A pseudo-terminal; its device can be made unopenable for anyone but root.
class Pty {
public:
    Pty() {
        master_ = posix_openpt(O_RDWR | O_NOCTTY);
        if (master_ < 0 || grantpt(master_) != 0 || unlockpt(master_) != 0) return;
        path_ = QString::fromLocal8Bit(ptsname(master_));
    }
    ~Pty() {
        if (master_ >= 0) ::close(master_);
    }
    bool ok() const { return !path_.isEmpty(); }
    const QString &path() const { return path_; }
    bool lockOut() const { return ::chmod(QFile::encodeName(path_).constData(), 0) == 0; }

private:
    int master_ = -1;
    QString path_;
};

// For its lifetime the effective user is nobody when the process runs as root (permission checks
// follow the effective user); as anyone else it changes nothing.
class WithoutRoot {
public:
    WithoutRoot() {
        if (::geteuid() != 0) return;
        switched_ = ::seteuid(nobodyUid()) == 0;
        failed_ = !switched_;
    }
    ~WithoutRoot() {
        if (switched_ && ::seteuid(0) != 0) qFatal("could not become root again");
    }
    bool failed() const { return failed_; }

private:
    bool switched_ = false;
    bool failed_ = false;
};

// LCK..pts_3 for /dev/pts/3, as QSerialPort names its lock files.
QString lockName(const QString &device) {
    return QStringLiteral("LCK..") + device.mid(5).replace('/', '_');
}

// A lock file in the format QLockFile writes (PID, program, host), in the first lock folder
// QSerialPort uses (/var/lock, on Linux a link to /run/lock); removed at the end.
class LockFile {
public:
    LockFile(const QString &device, qint64 pid, const char *program)
        : path_(QStringLiteral("/var/lock/") + lockName(device)) {
        QFile f(path_);
        if (f.exists() || !f.open(QIODevice::WriteOnly)) {
            path_.clear();
            return;
        }
        f.write(QByteArray::number(pid) + '\n' + program + "\n\n");
    }
    ~LockFile() {
        if (!path_.isEmpty()) QFile::remove(path_);
    }
    bool ok() const { return !path_.isEmpty(); }
    const QString &path() const { return path_; }

private:
    QString path_;
};

QString openError(const QString &port) {
    SerialTransport t(SerialSettings{port, 9600});
    if (t.open()) return {};
    return t.errorString();
}

} // namespace

class TstSerialPermission : public QObject {
    Q_OBJECT
private slots:
    void permissionDeniedNamesTheGroupAndTheCommand() {
        Pty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        QVERIFY(pty.lockOut());
        QString why;
        {
            WithoutRoot user;
            if (user.failed()) QSKIP("running as root without the right to become nobody");
            why = openError(pty.path());
        }
        QVERIFY2(!why.isEmpty(), "the port opened although its mode is 000");
        QVERIFY2(why.contains(pty.path()), qPrintable(why));
        QVERIFY2(why.contains("'dialout' group"), qPrintable(why));
        QVERIFY2(why.contains("sudo usermod -aG dialout $USER"), qPrintable(why));
        QVERIFY2(why.contains("log out and back in"), qPrintable(why));
    }

    void gnssCliSaysItOnStandardError() {
        Pty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        QVERIFY(pty.lockOut());
        QProcess cli;
        const bool root = ::geteuid() == 0;
        if (root) {
            // As nobody from the start: root could open the device whatever its mode.
            cli.setChildProcessModifier([] {
                if (::setgroups(0, nullptr) != 0 || ::setgid(nobodyGid()) != 0 ||
                    ::setuid(nobodyUid()) != 0)
                    ::_exit(126);
            });
        }
        cli.start(QStringLiteral(GNSS_CLI_PATH),
                  {"monitor", "--port", pty.path(), "--duration", "5"});
        // As nobody, a build under a private folder (/root is 0700) cannot even be started.
        if (root && !cli.waitForStarted(5000) && cli.error() == QProcess::FailedToStart)
            QSKIP("nobody cannot start " GNSS_CLI_PATH " (a folder on its path is private)");
        QVERIFY(cli.waitForFinished(20000));
        if (root && cli.exitCode() == 126)
            QSKIP("running as root without the right to become nobody");
        const QByteArray err = cli.readAllStandardError();
        if (root && err.contains("Permission denied") && !err.contains(pty.path().toUtf8()))
            QSKIP(qPrintable("nobody cannot run " GNSS_CLI_PATH ": " + err));
        QCOMPARE(cli.exitCode(), 1);
        QVERIFY2(err.contains("'dialout' group"), err.constData());
        QVERIFY2(err.contains("sudo usermod -aG dialout $USER"), err.constData());
        QVERIFY2(cli.readAllStandardOutput().isEmpty(), "an error is not data");
    }

    void aBusyPortNamesItsHolderNotTheGroup() {
        // QSerialPort reports a port another program holds (its lock file) as a permission
        // error too; joining a group would not help there. The lock file says who holds it.
        Pty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        SerialTransport first(SerialSettings{pty.path(), 9600});
        if (!first.open())
            QSKIP(qPrintable("cannot open the pseudo-terminal: " + first.errorString()));
        const QString why = openError(pty.path());
        if (why.isEmpty()) QSKIP("this system lets a port be opened twice (no lock files)");
        QVERIFY2(!why.contains("dialout"), qPrintable(why));
        const QString self = QFileInfo(QCoreApplication::applicationFilePath()).fileName();
        QVERIFY2(why.contains(QStringLiteral("%1 (process %2) has it open (lock file ")
                                      .arg(self.left(15))
                                      .arg(QCoreApplication::applicationPid())),
                 qPrintable(why));
        QVERIFY2(why.contains(lockName(pty.path())), qPrintable(why));
    }

    // A lock whose process runs but has not the port open: between its closing the port and
    // removing the lock, or a lock it leaked. Written here as a lock of `sleep`'s.
    void aLockWhoseHolderHasNotThePortOpenSaysSo() {
        Pty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        QProcess sleeper;
        sleeper.start(QStringLiteral("sleep"), {QStringLiteral("30")});
        if (!sleeper.waitForStarted(5000)) QSKIP("no sleep(1) to hold the lock");
        const qint64 pid = sleeper.processId();
        const LockFile lock(pty.path(), pid, "sleep");
        if (!lock.ok()) QSKIP("the lock folder is not writable here");
        const QString why = openError(pty.path());
        sleeper.kill();
        sleeper.waitForFinished(5000);
        QVERIFY2(why.contains(QStringLiteral("Its lock file %1 names sleep (process %2), which "
                                             "does not have it open")
                                      .arg(lock.path())
                                      .arg(pid)),
                 qPrintable(why));
        QVERIFY2(!why.contains("dialout"), qPrintable(why));
    }

    // Another user's lock, left by a process that has ended: QSerialPort cannot remove it (the
    // lock folder is sticky), so the port stays locked until the file goes.
    void aLockLeftByAnEndedProcessIsNamed() {
        if (::geteuid() != 0) QSKIP("needs root to leave a lock another user cannot remove");
        Pty pty;
        if (!pty.ok()) QSKIP("no pseudo-terminal");
        QVERIFY(::chmod(QFile::encodeName(pty.path()).constData(), 0666) == 0);
        QProcess ended;
        ended.start(QStringLiteral("true"), {});
        if (!ended.waitForStarted(5000)) QSKIP("no true(1) to take a process id from");
        const qint64 pid = ended.processId();
        QVERIFY(ended.waitForFinished(5000));
        const LockFile lock(pty.path(), pid, "gnss-cli");
        if (!lock.ok()) QSKIP("the lock folder is not writable here");
        if (!QFileInfo(QFileInfo(lock.path()).path()).permissions().testFlag(QFile::WriteOther))
            QSKIP("the lock folder is not shared by all users");
        QString why;
        {
            WithoutRoot user;
            if (user.failed()) QSKIP("running as root without the right to become nobody");
            why = openError(pty.path());
        }
        QVERIFY2(why.contains(QStringLiteral("Its lock file %1 is left from process %2, which has "
                                             "ended: delete that file.")
                                      .arg(lock.path())
                                      .arg(pid)),
                 qPrintable(why));
    }

    void aMissingPortGetsNoAdvice() {
        const QString why = openError(QStringLiteral("/dev/ttyGNSSWorkbenchNoSuchPort"));
        QVERIFY(!why.isEmpty());
        QVERIFY2(!why.contains("dialout") && !why.contains("Another program"), qPrintable(why));
    }

    // The names a port goes by: the window refuses a second receiver on a port one has open
    // whichever of them each was given, and the messages above name the device by its path.
    void aPortIsOneDeviceByAnyOfItsNames_data() {
        QTest::addColumn<QString>("a");
        QTest::addColumn<QString>("b");
        QTest::addColumn<bool>("same");
        QTest::newRow("name and path") << "ttyUSB0"
                                       << "/dev/ttyUSB0" << true;
        QTest::newRow("pseudo-terminal") << "pts/3"
                                         << "/dev/pts/3" << true;
        QTest::newRow("two ports") << "ttyUSB0"
                                   << "ttyUSB1" << false;
        QTest::newRow("link to a device") << "LINK"
                                          << "/dev/null" << true;
        QTest::newRow("link and another") << "LINK"
                                          << "/dev/zero" << false;
        QTest::newRow("link by ./") << "./LINK"
                                    << "/dev/null" << true;
        QTest::newRow("link by ../") << "../LINK"
                                     << "/dev/null" << true;
    }
    void aPortIsOneDeviceByAnyOfItsNames() {
        QFETCH(QString, a);
        QFETCH(QString, b);
        QFETCH(bool, same);
        QTemporaryDir dir; // a /dev/serial/by-id/ name: a link to the device
        QVERIFY(dir.isValid());
        const QString link = dir.filePath("usb-NVS_NV08C-if00");
        QVERIFY(QFile::link("/dev/null", link));
        // "./LINK" and "../LINK": the link from the folder it is in, or from one below it.
        QVERIFY(QDir(dir.path()).mkdir("below"));
        const QString before = QDir::currentPath();
        const auto back = qScopeGuard([&] { QDir::setCurrent(before); });
        QVERIFY(QDir::setCurrent(a == "../LINK" ? dir.filePath("below") : dir.path()));
        if (a == "LINK")
            a = link;
        else if (a.endsWith("LINK"))
            a = a.chopped(4) + QFileInfo(link).fileName();
        QCOMPARE(gnss::link::sameSerialDevice(a, b), same);
        QCOMPARE(gnss::link::sameSerialDevice(b, a), same);
        QCOMPARE(gnss::link::serialDevicePath("ttyACM0"), QStringLiteral("/dev/ttyACM0"));
        QCOMPARE(gnss::link::serialDevicePath(link), link);
        QCOMPARE(gnss::link::serialDevicePath("./rover"), QStringLiteral("./rover"));
        QCOMPARE(gnss::link::serialDevicePath("../rover"), QStringLiteral("../rover"));
        QCOMPARE(gnss::link::serialDevicePath("pts/3"), QStringLiteral("/dev/pts/3"));
    }

    // A receiver known by its USB serial number is opened again under the name it has after an
    // unplug (ttyUSB0 → ttyUSB1), whichever name the user first opened it by. Two
    // pseudo-terminals stand for the device before and after; the listing is the enumerator's.
    void aPortIsFoundAgainUnderItsNewName_data() {
        QTest::addColumn<QString>("given");
        QTest::newRow("path") << "PATH";
        QTest::newRow("name under /dev") << "UNDER-DEV";
        QTest::newRow("by-id link") << "LINK";
    }
    void aPortIsFoundAgainUnderItsNewName() {
        QFETCH(QString, given);
        Pty before, after;
        if (!before.ok() || !after.ok()) QSKIP("no pseudo-terminal");
        QVERIFY(before.path().startsWith("/dev/"));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString link = dir.filePath("usb-NVS_NV08C-if00");
        QVERIFY(QFile::link(before.path(), link));
        const QString name = given == "PATH"        ? before.path()
                             : given == "UNDER-DEV" ? before.path().mid(5) // "pts/3"
                                                    : link;
        const auto usb = [](const QString &portName, const QString &location) {
            gnss::link::PortInfo p;
            p.portName = portName;
            p.systemLocation = location;
            p.serialNumber = QStringLiteral("NV08C-0042");
            p.vendorId = 0x0403;
            p.productId = 0x6001;
            return p;
        };
        QList<gnss::link::PortInfo> listed{usb("ttyUSB0", before.path())};
        SerialTransport port(SerialSettings{name, 9600}, [&] { return listed; });
        QVERIFY2(port.open(), qPrintable(port.errorString()));
        QVERIFY(port.description().startsWith(name + " "));
        port.close();
        listed = {usb("ttyUSB1", after.path())}; // unplugged and back under another name
        QVERIFY2(port.open(), qPrintable(port.errorString()));
        QVERIFY2(port.description().startsWith(after.path() + " "), qPrintable(port.description()));
    }
};

QTEST_GUILESS_MAIN(TstSerialPermission)
#include "tst_serial_permission.moc"
