#pragma once
// A settings engine on the in-process simulator: transport, its decoder, command queue, engine,
// and a way to run one operation to its end.
#include "builtin/dialects.h"
#include "builtin/simulators.h"

#include "common/simulator_transport.h"
#include "config/settings_engine.h"
#include "link/command_queue.h"
#include "link/sentence_stream.h"

#include <QSignalSpy>
#include <QTest>

#include <functional>

namespace gnss::config::test {

inline const DialectRegistry &registry() {
    static const DialectRegistry r = makeBuiltinRegistry();
    return r;
}

struct EngineRig {
    explicit EngineRig(const QString &dialectId)
        : dialect(registry().find(dialectId.toStdString())),
          sim(sim::builtinSimulators(), dialectId, 7), stream(&sim, registry()),
          queue(&sim, &stream) {
        sim.setSpeed(2.0);
        opened = sim.open();
        queue.setDialect(dialect);
        engine.attach(&queue, dialect, &sim);
    }
    // Starts an operation and waits for its report.
    OperationReport run(const std::function<bool()> &start, int timeoutMs = 60000) {
        QSignalSpy spy(&engine, &SettingsEngine::finished);
        start();
        if (spy.isEmpty()) spy.wait(timeoutMs);
        return engine.lastReport();
    }
    OperationReport readAll() {
        return run([this] { return engine.read(); });
    }
    OperationReport apply(const std::vector<KeyValue> &v) {
        return run([&] { return engine.apply(v); });
    }

    const Dialect *dialect;
    link::SimulatorTransport sim;
    link::SentenceStream stream;
    link::CommandQueue queue;
    SettingsEngine engine;
    bool opened = false;
};

// What went wrong in a report, for failure messages.
inline QByteArray describe(const OperationReport &r) {
    QString s = r.title + ": " + r.error;
    for (const auto &c : r.commands)
        s += QString("\n  %1 -> %2 (%3)").arg(c.sentence, link::outcomeName(c.outcome), c.detail);
    for (const auto &c : r.checks)
        s += QString("\n  %1 = %2: %3 (reported '%4')")
                     .arg(QString::fromStdString(c.key), QString::fromStdString(c.wanted),
                          verdictName(c.verdict), QString::fromStdString(c.reported));
    return s.toUtf8();
}

} // namespace gnss::config::test

// QtTest cuts long messages: the whole report goes to the log first.
#define VERIFY_REPORT(expr)                                                                        \
    do {                                                                                           \
        const auto report_ = (expr);                                                               \
        if (!report_.ok()) qWarning().noquote() << gnss::config::test::describe(report_);          \
        QVERIFY(report_.ok());                                                                     \
    } while (false)
