#pragma once
// Test helper: `gnss-cli serve ARGS` running in the background (stopped at the end), and what it
// says on standard error waited for: the port its caster listens on, a client served.
#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStringList>

namespace gnss::test {

struct ServeProcess {
    QProcess proc;
    QByteArray err;
    explicit ServeProcess(
            const QStringList &args,
            const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment()) {
        proc.setProcessEnvironment(env);
        proc.start(QStringLiteral(GNSS_CLI_PATH), QStringList{"serve"} + args);
        proc.waitForStarted(5000);
    }
    ~ServeProcess() {
        if (proc.state() != QProcess::NotRunning) {
            proc.terminate();
            if (!proc.waitForFinished(5000)) proc.kill();
        }
    }
    // Waits (up to `ms`) for standard error to say `pattern`; its first capture, or empty.
    QString waitFor(const QString &pattern, int ms = 10000) {
        const QRegularExpression re(pattern);
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            err += proc.readAllStandardError();
            const auto m = re.match(QString::fromUtf8(err));
            if (m.hasMatch()) return m.captured(1).isEmpty() ? m.captured(0) : m.captured(1);
            if (proc.state() == QProcess::NotRunning) break;
            proc.waitForReadyRead(100);
        }
        err += proc.readAllStandardError();
        return {};
    }
    quint16 ntripPort() {
        return quint16(waitFor("NTRIP caster on 127\\.0\\.0\\.1:(\\d+)").toUInt());
    }
};

} // namespace gnss::test
