#pragma once
// Columns sized to their contents without measuring every cell on every change.
//
// QHeaderView::ResizeToContents measures a column's cells again (sizeHintForColumn) whenever any
// of them changes. The satellites table is rewritten whole at every epoch, so at 20 Hz that
// measuring was a third of the GUI thread. FittedColumns sizes the columns when rows come or go
// (inserted, removed, a reset, a new layout), on the next turn of the event loop, and at most
// once every `intervalMs` when only values change. A column the user resizes keeps the user's
// width; the last section, when it stretches, is left to stretch.
#include <QObject>
#include <QSet>
#include <QTimer>

class QAbstractItemView;
class QHeaderView;

namespace gnss::ui {

class FittedColumns : public QObject {
    Q_OBJECT
public:
    // `view` must have its model; `header` is its horizontal header (QTableView) or its header
    // (QTreeView). Both outlive this object, which is a child of the view.
    FittedColumns(QAbstractItemView *view, QHeaderView *header, int intervalMs = 1000);

    // Sizes every column now (what the timer does).
    void fit();
    // How many times the columns were measured: what the tests count.
    int fits() const { return fits_; }

private:
    void soon();
    void later();

    QAbstractItemView *view_;
    QHeaderView *header_;
    int intervalMs_;
    QTimer timer_;
    QSet<int> userSized_;
    bool fitting_ = false;
    int fits_ = 0;
};

} // namespace gnss::ui
