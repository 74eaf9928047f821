#include "views/value_grid.h"

#include "models/value_format.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>

namespace gnss::ui {

QGroupBox *valueGroup(const QString &title, QGridLayout *&grid) {
    auto *group = new QGroupBox(title);
    grid = new QGridLayout(group);
    grid->setColumnStretch(1, 1);
    return group;
}

QLabel *addValueRow(QGridLayout *grid, const QString &name, const char *objectName) {
    const int row = grid->rowCount();
    grid->addWidget(new QLabel(name + QLatin1Char(':')), row, 0);
    auto *value = new QLabel(fmt::dash());
    value->setObjectName(QString::fromLatin1(objectName));
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    grid->addWidget(value, row, 1);
    return value;
}

} // namespace gnss::ui
