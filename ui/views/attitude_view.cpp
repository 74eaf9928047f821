#include "views/attitude_view.h"
#include "models/refresh_intervals.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "views/value_grid.h"
#include "widgets/read_only_table.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace gnss::ui {

AttitudeView::AttitudeView(ReceiverStateModel *model, QWidget *parent)
    : QWidget(parent), model_(model), timer_(new QTimer(this)) {
    auto *outer = new QVBoxLayout(this);
    auto *top = new QHBoxLayout;

    QGridLayout *g = nullptr;
    auto *att = valueGroup(tr("Attitude"), g);
    roll_ = addValueRow(g, tr("Roll"), "attitudeRoll");
    pitch_ = addValueRow(g, tr("Pitch"), "attitudePitch");
    yaw_ = addValueRow(g, tr("Yaw"), "attitudeYaw");
    time_ = addValueRow(g, tr("Time"), "attitudeTime");
    top->addWidget(att, 1);

    auto *acc = valueGroup(tr("Acceleration"), g);
    accNorth_ = addValueRow(g, tr("North"), "attitudeAccNorth");
    accEast_ = addValueRow(g, tr("East"), "attitudeAccEast");
    accDown_ = addValueRow(g, tr("Down"), "attitudeAccDown");
    g->setRowStretch(g->rowCount(), 1);
    top->addWidget(acc, 1);
    outer->addLayout(top);

    auto *tm = new QGroupBox(tr("Time marks (newest first)"));
    auto *tl = new QVBoxLayout(tm);
    markCount_ = new QLabel(fmt::dash());
    markCount_->setObjectName("timeMarkCount");
    tl->addWidget(markCount_);
    marks_ = readOnlyTable(ColumnCount, "timeMarkTable");
    setHeaders();
    marks_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    marks_->setSelectionBehavior(QAbstractItemView::SelectRows);
    marks_->setAlternatingRowColors(true);
    marks_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    tl->addWidget(marks_);
    outer->addWidget(tm, 1);

    startRefreshTimer(*timer_, kLiveRefreshMs, this, &AttitudeView::poll);
    refresh();
}

void AttitudeView::poll() {
    if (model_->epochCount() != shownEpochs_) refresh();
}

void AttitudeView::setHeaders() {
    const QString zone = prefs_.time == TimeZoneChoice::Utc ? tr("UTC") : tr("Local time");
    marks_->setHorizontalHeaderLabels({tr("Counter"), tr("GPS time of week (s)"), zone,
                                       tr("Latitude"), tr("Longitude"),
                                       tr("Altitude MSL (%1)").arg(fmt::lengthUnit(prefs_.units))});
}

void AttitudeView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    setHeaders();
    shownMarks_ = ~std::size_t(0); // rewrite the table
    refresh();
}

void AttitudeView::refresh() {
    shownEpochs_ = model_->epochCount();
    const ReceiverState &st = model_->state();
    const AttitudeState &a = st.attitude;
    const QString acc = tr("m/s\u00B2");
    roll_->setText(fmt::angle(a.roll, 2));
    pitch_->setText(fmt::angle(a.pitch, 2));
    yaw_->setText(fmt::angle(a.yaw, 2));
    time_->setText(fmt::time(st.epoch.date, a.time, prefs_.time));
    accNorth_->setText(fmt::number(a.accNorth, 3, acc));
    accEast_->setText(fmt::number(a.accEast, 3, acc));
    accDown_->setText(fmt::number(a.accDown, 3, acc));

    // Rebuild the table only when the events changed: the count or the newest one.
    const auto &tm = st.timeMarks;
    const std::optional<std::int64_t> newestCounter = tm.empty() ? std::nullopt : tm.back().counter;
    const std::optional<double> newestTow = tm.empty() ? std::nullopt : tm.back().towSeconds;
    if (tm.size() == shownMarks_ && newestCounter == shownCounter_ && newestTow == shownTow_)
        return;
    shownMarks_ = tm.size();
    shownCounter_ = newestCounter;
    shownTow_ = newestTow;
    markCount_->setText(tm.empty() ? tr("No time marks yet")
                                   : tr("%n time mark(s)", nullptr, int(tm.size())));
    const int rows = std::min<int>(static_cast<int>(tm.size()), kMaxRows);
    const double k = fmt::lengthFactor(prefs_.units);
    marks_->setUpdatesEnabled(false);
    // Columns sized to their contents once, after the rebuild: sized while the cells change,
    // every cell's change measured every row again (500 rows x 6 columns, squared), and the GUI
    // thread spent seconds per new time mark once the table filled (the soak found it).
    QHeaderView *header = marks_->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Interactive);
    marks_->setRowCount(rows);
    for (int row = 0; row < rows; ++row) {
        const TimeMarkEvent &e = tm[tm.size() - 1 - static_cast<std::size_t>(row)]; // newest first
        const QString cells[ColumnCount] = {fmt::count(e.counter),
                                            fmt::number(e.towSeconds, 6),
                                            fmt::time(std::nullopt, e.utc, prefs_.time, false),
                                            fmt::latitude(e.lat, prefs_.coordinates),
                                            fmt::longitude(e.lon, prefs_.coordinates),
                                            e.altMsl ? fmt::number(*e.altMsl * k, 3) : fmt::dash()};
        for (int c = 0; c < ColumnCount; ++c) {
            QTableWidgetItem *item = marks_->item(row, c);
            if (!item) {
                item = new QTableWidgetItem;
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                marks_->setItem(row, c, item);
            }
            item->setText(cells[c]);
        }
    }
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    marks_->setUpdatesEnabled(true);
}

} // namespace gnss::ui
