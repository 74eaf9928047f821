#pragma once
// The layout the log viewer's panels share: the panel named (for tests and style sheets), a
// column with 4 px margins and, at its top, a row for the panel's controls.
#include <QBoxLayout>
#include <QWidget>

namespace gnss::ui {

struct PanelLayout {
    QVBoxLayout *column;
    QHBoxLayout *controls; // already the column's first item
};

inline PanelLayout panelLayout(QWidget *panel, const char *objectName) {
    panel->setObjectName(objectName);
    auto *column = new QVBoxLayout(panel);
    column->setContentsMargins(4, 4, 4, 4);
    auto *controls = new QHBoxLayout;
    column->addLayout(controls);
    return {column, controls};
}

} // namespace gnss::ui
