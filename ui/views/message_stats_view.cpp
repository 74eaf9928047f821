#include "views/message_stats_view.h"

#include "models/message_stats_model.h"

#include <QHeaderView>
#include <QSortFilterProxyModel>

namespace gnss::ui {

MessageStatsView::MessageStatsView(MessageStatsModel *model, QWidget *parent) : QTableView(parent) {
    setObjectName("messageStats");
    auto *proxy = new QSortFilterProxyModel(this);
    proxy->setSourceModel(model);
    proxy->setSortRole(Qt::UserRole);
    setModel(proxy);
    setSortingEnabled(true);
    sortByColumn(MessageStatsModel::Address, Qt::AscendingOrder);
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->setStretchLastSection(true);
    setAlternatingRowColors(true);
    setSelectionBehavior(QAbstractItemView::SelectRows);
}

} // namespace gnss::ui
