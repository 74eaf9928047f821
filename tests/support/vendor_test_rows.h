#pragma once
// A QtTest _data row of text columns in one call, for the tables of (key, value, what the result
// must say) the vendor, config and schema suites keep: QTest::newRow(name) << each column.
#include <QString>
#include <QTest>

#include <initializer_list>

namespace gnss::test {

inline void textRow(const char *name, std::initializer_list<QString> columns) {
    QTestData &row = QTest::newRow(name);
    for (const QString &c : columns) row << c;
}

} // namespace gnss::test
