#pragma once
// Test helper: the text of a view's label, found by its object name.
#include <QLabel>
#include <QString>
#include <QWidget>

namespace gnss::test {

inline QString labelText(const QWidget &w, const char *objectName) {
    auto *l = w.findChild<QLabel *>(QString::fromLatin1(objectName));
    return l ? l->text() : QStringLiteral("<missing %1>").arg(QString::fromLatin1(objectName));
}

} // namespace gnss::test
