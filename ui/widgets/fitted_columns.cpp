#include "widgets/fitted_columns.h"

#include <QAbstractItemView>
#include <QHeaderView>

#include <algorithm>

namespace gnss::ui {

FittedColumns::FittedColumns(QAbstractItemView *view, QHeaderView *header, int intervalMs)
    : QObject(view), view_(view), header_(header), intervalMs_(intervalMs) {
    header_->setSectionResizeMode(QHeaderView::Interactive);
    timer_.setSingleShot(true);
    connect(&timer_, &QTimer::timeout, this, &FittedColumns::fit);
    QAbstractItemModel *model = view_->model();
    Q_ASSERT(model);
    connect(model, &QAbstractItemModel::rowsInserted, this, &FittedColumns::soon);
    connect(model, &QAbstractItemModel::rowsRemoved, this, &FittedColumns::soon);
    connect(model, &QAbstractItemModel::modelReset, this, &FittedColumns::soon);
    connect(model, &QAbstractItemModel::layoutChanged, this, &FittedColumns::soon);
    connect(model, &QAbstractItemModel::headerDataChanged, this, &FittedColumns::soon);
    connect(model, &QAbstractItemModel::dataChanged, this, &FittedColumns::later);
    connect(header_, &QHeaderView::sectionResized, this, [this](int section) {
        if (!fitting_) userSized_.insert(section);
    });
    soon();
}

void FittedColumns::soon() {
    // Several changes in one turn of the event loop are measured once.
    if (!timer_.isActive() || timer_.remainingTime() > 0) timer_.start(0);
}

void FittedColumns::later() {
    if (!timer_.isActive()) timer_.start(intervalMs_);
}

void FittedColumns::fit() {
    timer_.stop();
    ++fits_;
    fitting_ = true;
    const int count = header_->count();
    const int last = header_->stretchLastSection() ? header_->logicalIndex(count - 1) : -1;
    for (int i = 0; i < count; ++i) {
        if (header_->isSectionHidden(i) || i == last || userSized_.contains(i)) continue;
        const int width = std::max(view_->sizeHintForColumn(i), header_->sectionSizeHint(i));
        if (width > 0 && width != header_->sectionSize(i)) header_->resizeSection(i, width);
    }
    fitting_ = false;
}

} // namespace gnss::ui
