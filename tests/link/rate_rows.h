#pragma once
// The line speeds baud detection is tested at, from 4800 to 921600: a QtTest data row each.
#include <QString>
#include <QTest>

namespace gnss::link::test {

// A row per speed, named by it, in the column "rate".
inline void everyRateRows() {
    QTest::addColumn<int>("rate");
    for (int r : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
        QTest::newRow(qPrintable(QString::number(r))) << r;
}

} // namespace gnss::link::test
