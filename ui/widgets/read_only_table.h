#pragma once
// The tables the views show to be read, not edited (log events, log summary, time marks, RTCM
// message types): named, no row numbers, no editing, the last column taking the room left.
#include <QTableWidget>

namespace gnss::ui {

QTableWidget *readOnlyTable(int columns, const char *objectName, QWidget *parent = nullptr);

} // namespace gnss::ui
