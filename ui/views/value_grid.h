#pragma once
// The "name: value" grids of the panels that list single values (RTK, attitude): a titled group
// whose grid has the names on the left and the values, right-aligned and selectable, on the
// right; a value reads "—" until the panel writes it.
#include <QString>

class QGridLayout;
class QGroupBox;
class QLabel;

namespace gnss::ui {

// A group box titled `title` with an empty grid (`grid`) whose value column stretches.
QGroupBox *valueGroup(const QString &title, QGridLayout *&grid);
// Appends the row "name:" and a value label named `objectName`, which it returns.
QLabel *addValueRow(QGridLayout *grid, const QString &name, const char *objectName);

} // namespace gnss::ui
