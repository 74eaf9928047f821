#pragma once
// QtTest data rows over the built-in dialects: the registry (and the simulators' table) is the
// one list of vendors, so a suite that runs once per family asks them rather than naming them.
#include "builtin_registry.h"

#include <QString>
#include <QTest>

#include <string>

namespace gnss::test {

// A "dialect" column and a row per built-in family that has settings and a simulated receiver
// (the families a settings suite can drive end to end), in registry order.
inline void addSettingsDialectRows() {
    QTest::addColumn<QString>("dialect");
    for (const Dialect *d : builtinRegistry().dialects())
        if (!d->settings.empty() && sim::builtinSimulators().has(d->id)) {
            const std::string id(d->id);
            QTest::newRow(id.c_str()) << QString::fromStdString(id);
        }
}

} // namespace gnss::test
