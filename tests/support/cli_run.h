#pragma once
// Test helper: run a built program (gnss-cli, gnss-sim) to its end and keep what it said: the
// exit code, standard output and standard error; and split gnss-cli's output into its JSON lines.
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace gnss::test {

struct Run {
    int exitCode =
            -1; // -1 unless the program ended by itself (it crashed, did not start, timed out)
    QProcess::ExitStatus status = QProcess::CrashExit;
    QByteArray out, err;
};

// Starts `program`, writes `input` (if any) to its standard input and closes it, and waits up to
// `timeoutMs` for the program to end; one that has not by then is killed (and counts as crashed).
// It runs in `workingDir` when one is given.
inline Run runProgram(const QString &program, const QStringList &args, const QByteArray &input = {},
                      int timeoutMs = 120000,
                      const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment(),
                      const QString &workingDir = {}) {
    QProcess p;
    p.setProcessEnvironment(env);
    if (!workingDir.isEmpty()) p.setWorkingDirectory(workingDir);
    p.start(program, args);
    p.waitForStarted();
    if (!input.isEmpty()) p.write(input);
    p.closeWriteChannel();
    const bool ended = p.waitForFinished(timeoutMs);
    if (!ended) {
        p.kill();
        p.waitForFinished();
    }
    Run r;
    r.status = ended ? p.exitStatus() : QProcess::CrashExit;
    r.exitCode = r.status == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

#ifdef GNSS_CLI_PATH
// gnss-cli (the one this build made) with `args`.
inline Run runCli(const QStringList &args, const QByteArray &input = {}, int timeoutMs = 120000) {
    return runProgram(QStringLiteral(GNSS_CLI_PATH), args, input, timeoutMs);
}
#endif

// The JSON objects of a program's output, one a line (empty lines skipped).
inline QList<QJsonObject> jsonLines(const QByteArray &out) {
    QList<QJsonObject> l;
    for (const auto &line : out.split('\n'))
        if (!line.isEmpty()) l << QJsonDocument::fromJson(line).object();
    return l;
}

} // namespace gnss::test
