#pragma once
// gnss-cli ntrip run to its end while the test's own event loop keeps serving the test caster
// (tests/support/test_caster.h lives on the test's thread): the password in TEST_NTRIP_PW
// (`--password-env TEST_NTRIP_PW`), `feed` called every 100 ms to push data.
#include "cli_run.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QSignalSpy>
#include <QTimer>

#include <functional>

namespace gnss::test {

inline Run runNtripCli(const QStringList &args, const QString &password,
                       const std::function<void()> &feed = {}, const QString &dir = {},
                       int timeoutMs = 60000) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("TEST_NTRIP_PW"), password);
    p.setProcessEnvironment(env);
    if (!dir.isEmpty()) p.setWorkingDirectory(dir);
    QTimer pump;
    if (feed) {
        QObject::connect(&pump, &QTimer::timeout, feed);
        pump.start(100);
    }
    QSignalSpy done(&p, &QProcess::finished);
    p.start(QStringLiteral(GNSS_CLI_PATH), args);
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

} // namespace gnss::test
