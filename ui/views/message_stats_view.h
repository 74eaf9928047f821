#pragma once
// MessageStatsView: per address count, rate in Hz, last seen, checksum and decode errors;
// sortable by any column.
#include <QTableView>

namespace gnss::ui {

class MessageStatsModel;

class MessageStatsView : public QTableView {
    Q_OBJECT
public:
    explicit MessageStatsView(MessageStatsModel *model, QWidget *parent = nullptr);
};

} // namespace gnss::ui
