#pragma once
// Test helper: the first tab of a visible dock group whose title is cut ("Ре…"), described with
// the room it had; empty when every title is whole.
#include <QApplication>
#include <QString>
#include <QTabBar>
#include <QWidget>

namespace gnss::test {

inline QString cutTabTitle(const QWidget &window) {
    QApplication::processEvents();
    for (QTabBar *bar : window.findChildren<QTabBar *>()) {
        if (!bar->isVisible()) continue;
        for (int i = 0; i < bar->count(); ++i) {
            const int need = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
            if (bar->tabRect(i).width() <= need)
                return QStringLiteral("tab '%1': %2 px for %3 px of text")
                        .arg(bar->tabText(i))
                        .arg(bar->tabRect(i).width())
                        .arg(need);
        }
    }
    return {};
}

} // namespace gnss::test
