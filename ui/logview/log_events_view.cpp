#include "logview/log_events_view.h"
#include "logview/panel_layout.h"
#include "widgets/read_only_table.h"

#include "core/dialect_registry.h"
#include "style/gnss_style.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {
constexpr logview::EventKind kKinds[] = {
        logview::EventKind::FixChange,   logview::EventKind::Gap,
        logview::EventKind::LinkGap,     logview::EventKind::ChecksumErrors,
        logview::EventKind::TimeJump,    logview::EventKind::DialectChange,
        logview::EventKind::TimeMark,    logview::EventKind::Jamming,
        logview::EventKind::BaseStation,
};

QString eventTime(const logview::LogEvent &e) {
    logview::EpochRecord r;
    r.utcMs = e.utcMs;
    if (e.dated) r.flags = logview::kDateKnown;
    return QString::fromStdString(logview::formatTime(r));
}
} // namespace

LogEventsView::LogEventsView(LogCursor *cursor, const DialectRegistry &registry, QWidget *parent)
    : QWidget(parent), cursor_(cursor), registry_(registry) {
    const auto [layout, row] = panelLayout(this, "logEventsView");
    row->addWidget(new QLabel(tr("Show:"), this));
    filter_ = new QComboBox(this);
    filter_->setObjectName("eventFilter");
    filter_->addItem(tr("All events"), -1);
    for (auto k : kKinds) filter_->addItem(kindName(k), int(k));
    row->addWidget(filter_, 1);
    export_ = new QPushButton(tr("Export CSV…"), this);
    export_->setObjectName("exportEvents");
    row->addWidget(export_);
    count_ = new QLabel(this);
    count_->setObjectName("eventCount");
    layout->addWidget(count_);
    table_ = readOnlyTable(3, "eventTable", this);
    table_->setHorizontalHeaderLabels({tr("Time"), tr("Event"), tr("Details")});
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    layout->addWidget(table_, 1);
    connect(filter_, &QComboBox::currentIndexChanged, this, &LogEventsView::reload);
    connect(export_, &QPushButton::clicked, this, &LogEventsView::exportRequested);
    connect(cursor_, &LogCursor::indexChanged, this, &LogEventsView::reload);
    connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) {
        bool ok = false;
        const qulonglong epoch = table_->item(row, 0)->data(Qt::UserRole).toULongLong(&ok);
        if (ok) cursor_->seek(std::size_t(epoch), true);
    });
    reload();
}

QString LogEventsView::kindName(logview::EventKind k) {
    switch (k) {
    case logview::EventKind::FixChange: return tr("Fix change");
    case logview::EventKind::Gap: return tr("Data gap");
    case logview::EventKind::LinkGap: return tr("Link lost");
    case logview::EventKind::ChecksumErrors: return tr("Checksum errors");
    case logview::EventKind::TimeJump: return tr("Time jump");
    case logview::EventKind::DialectChange: return tr("Receiver change");
    case logview::EventKind::TimeMark: return tr("Time mark");
    case logview::EventKind::Jamming: return tr("Jamming");
    case logview::EventKind::BaseStation: return tr("Base station");
    }
    return {};
}

QString LogEventsView::describe(const logview::LogEvent &e) const {
    const logview::LogView *log = cursor_->log();
    // The epoch and the one before, null when there is none (filled step by step: a conditional
    // of two optionals made GCC warn that their members may be read uninitialised).
    std::optional<logview::EpochRecord> curRec, prevRec;
    if (log) {
        curRec = log->epoch(e.epoch);
        if (e.epoch > 0) prevRec = log->epoch(e.epoch - 1);
    }
    const logview::EpochRecord *cur = curRec ? &*curRec : nullptr;
    const logview::EpochRecord *prev = prevRec ? &*prevRec : nullptr;
    auto dialect = [this](int d) {
        const auto all = registry_.dialects();
        const Dialect *x =
                d > 0 && std::size_t(d) <= all.size() ? all[std::size_t(d - 1)] : nullptr;
        return x ? QString::fromLatin1(x->displayName.data(), int(x->displayName.size()))
                 : tr("standard NMEA");
    };
    // Numbers the engine wrote (seconds of a gap, errors of a burst), in the user's words.
    QList<double> numbers;
    static const QRegularExpression number(QStringLiteral("[0-9]+(\\.[0-9]+)?"));
    for (auto it = number.globalMatch(QString::fromStdString(e.text)); it.hasNext();)
        numbers << it.next().captured().toDouble();
    switch (e.kind) {
    case logview::EventKind::FixChange:
        if (cur && prev)
            return tr("%1 → %2").arg(style::fixTypeLabel(prev->fixType()),
                                     style::fixTypeLabel(cur->fixType()));
        break;
    case logview::EventKind::Gap:
        if (!numbers.isEmpty()) return tr("no epochs for %1 s").arg(numbers.constFirst());
        break;
    case logview::EventKind::TimeJump:
        if (!numbers.isEmpty()) return tr("time went back %1 s").arg(numbers.constFirst());
        break;
    case logview::EventKind::ChecksumErrors:
        if (numbers.size() >= 2)
            return tr("checksum errors: %1, over epochs: %2").arg(numbers[0]).arg(numbers[1]);
        break;
    case logview::EventKind::DialectChange:
        if (cur)
            return prev && prev->dialect
                           ? tr("%1 sentences (after %2)")
                                     .arg(dialect(cur->dialect), dialect(prev->dialect))
                           : tr("%1 sentences").arg(dialect(cur->dialect));
        break;
    case logview::EventKind::TimeMark: return tr("time mark");
    case logview::EventKind::Jamming:
        if (cur) return cur->jamming == 2 ? tr("jamming detected") : tr("jamming cleared");
        break;
    case logview::EventKind::BaseStation:
        if (cur)
            return prev && prev->station >= 0
                           ? tr("station %1 (was %2)").arg(cur->station).arg(prev->station)
                           : tr("station %1").arg(cur->station);
        break;
    case logview::EventKind::LinkGap: break;
    }
    return QString::fromStdString(e.text); // what the engine said, when nothing else can
}

void LogEventsView::reload() {
    const logview::LogView *log = cursor_->log();
    events_ = log && !cursor_->empty() ? log->events() : std::vector<logview::LogEvent>{};
    const int want = filter_->currentData().toInt();
    table_->setRowCount(0);
    table_->setUpdatesEnabled(false);
    int row = 0;
    for (const logview::LogEvent &e : events_) {
        if (want >= 0 && int(e.kind) != want) continue;
        table_->insertRow(row);
        auto *t = new QTableWidgetItem(eventTime(e));
        t->setData(Qt::UserRole, qulonglong(e.epoch));
        t->setToolTip(tr("Epoch %1").arg(e.epoch));
        table_->setItem(row, 0, t);
        table_->setItem(row, 1, new QTableWidgetItem(kindName(e.kind)));
        table_->setItem(row, 2, new QTableWidgetItem(describe(e)));
        ++row;
    }
    table_->setUpdatesEnabled(true);
    export_->setEnabled(!events_.empty());
    if (!log)
        count_->setText(tr("No log open"));
    else if (cursor_->empty())
        count_->setText(tr("Indexing…"));
    else if (events_.empty())
        count_->setText(tr("No events: the fix never changed, and there were no gaps, resets or "
                           "checksum errors"));
    else
        count_->setText(tr("Events: %1; click one to go there").arg(events_.size()));
}

} // namespace gnss::ui
