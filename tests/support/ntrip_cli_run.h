#pragma once
// gnss-cli run to its end while the test's own event loop keeps serving its servers; and
// gnss-cli ntrip so, serving the test caster
// (tests/support/test_caster.h lives on the test's thread): the password in TEST_NTRIP_PW
// (`--password-env TEST_NTRIP_PW`), `feed` called every 100 ms to push data.
#include "cli_run.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QSignalSpy>
#include <QTimer>

#include <functional>

namespace gnss::test {

// gnss-cli run to its end while this thread's event loop goes on serving the test's own servers:
// `input` on its standard input (closed after), `env` added to its environment, `feed` called
// every 100 ms.
inline Run runCliServing(const QStringList &args, const QByteArray &input,
                         const QProcessEnvironment &env, const std::function<void()> &feed = {},
                         const QString &dir = {}, int timeoutMs = 60000) {
    QProcess p;
    p.setProcessEnvironment(env);
    if (!dir.isEmpty()) p.setWorkingDirectory(dir);
    QTimer pump;
    if (feed) {
        QObject::connect(&pump, &QTimer::timeout, feed);
        pump.start(100);
    }
    QSignalSpy done(&p, &QProcess::finished);
    p.start(QStringLiteral(GNSS_CLI_PATH), args);
    if (!input.isEmpty()) p.write(input);
    p.closeWriteChannel();
    done.wait(timeoutMs);
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished();
    }
    Run r;
    r.status = p.exitStatus();
    r.exitCode = r.status == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

inline Run runNtripCli(const QStringList &args, const QString &password,
                       const std::function<void()> &feed = {}, const QString &dir = {},
                       int timeoutMs = 60000) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("TEST_NTRIP_PW"), password);
    return runCliServing(args, {}, env, feed, dir, timeoutMs);
}

} // namespace gnss::test
