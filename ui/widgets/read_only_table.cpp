#include "widgets/read_only_table.h"

#include <QHeaderView>

namespace gnss::ui {

QTableWidget *readOnlyTable(int columns, const char *objectName, QWidget *parent) {
    auto *table = new QTableWidget(0, columns, parent);
    table->setObjectName(QString::fromLatin1(objectName));
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->horizontalHeader()->setStretchLastSection(true);
    return table;
}

} // namespace gnss::ui
