#include "logview/log_summary_view.h"
#include "widgets/read_only_table.h"

#include "qualify/accuracy_panel.h"
#include "style/gnss_style.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {
// Tall enough for the reference row, a few rows of statistics and a legible plot.
constexpr int kAccuracyHeight = 380;

QString seconds(const std::optional<double> &s) {
    return s ? QCoreApplication::translate("gnss::ui::LogSummaryView", "%1 s")
                           .arg(*s, 0, 'f', *s < 100 ? 1 : 0)
             : fmt::dash();
}
} // namespace

LogSummaryView::LogSummaryView(LogCursor *cursor, QWidget *parent)
    : QWidget(parent), cursor_(cursor) {
    setObjectName("logSummaryView");
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    title_ = new QLabel(this);
    title_->setObjectName("summaryTitle");
    title_->setWordWrap(true);
    layout->addWidget(title_);
    auto *row = new QHBoxLayout;
    stationary_ = new QCheckBox(tr("Spread of the epochs standing still"), this);
    stationary_->setObjectName("stationaryOnly");
    stationary_->setToolTip(tr("CEP and 2DRMS of the epochs whose speed is under 0.5 m/s (all "
                               "epochs when there are none)"));
    row->addWidget(stationary_, 1);
    auto *save = new QPushButton(tr("Save JSON…"), this);
    save->setObjectName("exportSummary");
    row->addWidget(save);
    layout->addLayout(row);
    // Tabs, not a split: the dock stays as short as the sky plot's group allows on a laptop.
    auto *tabs = new QTabWidget(this);
    tabs->setObjectName("summaryTabs");
    table_ = readOnlyTable(2, "summaryTable", tabs);
    table_->horizontalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    // The accuracy tab scrolls: its table and plot keep a readable height in a short dock, and
    // they never make the dock (and the window) taller than a laptop's screen.
    auto *scroll = new QScrollArea(tabs);
    scroll->setObjectName("logAccuracyScroll");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    accuracy_ = new AccuracyPanel(scroll);
    accuracy_->setObjectName("logAccuracy");
    accuracy_->setOrientation(Qt::Vertical);
    accuracy_->setMinimumHeight(kAccuracyHeight);
    scroll->setWidget(accuracy_);
    tabs->addTab(table_, tr("Range"));
    tabs->addTab(scroll, tr("Accuracy"));
    layout->addWidget(tabs, 1);
    accuracyLater_ = new QTimer(this);
    accuracyLater_->setSingleShot(true);
    accuracyLater_->setInterval(200);
    connect(accuracyLater_, &QTimer::timeout, this, &LogSummaryView::reloadAccuracy);
    connect(accuracy_, &AccuracyPanel::referenceChanged, this, &LogSummaryView::reloadAccuracy);
    connect(stationary_, &QCheckBox::toggled, this, &LogSummaryView::reload);
    connect(save, &QPushButton::clicked, this, &LogSummaryView::exportRequested);
    connect(cursor_, &LogCursor::indexChanged, this, &LogSummaryView::reload);
    connect(cursor_, &LogCursor::rangeChanged, this, &LogSummaryView::reload);
    reload();
}

bool LogSummaryView::stationaryOnly() const {
    return stationary_->isChecked();
}

void LogSummaryView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    accuracy_->setUnits(prefs.units);
    reload();
}

void LogSummaryView::reloadAccuracy() {
    compare::PositionSet positions;
    const logview::LogView *log = cursor_->log();
    if (log && !cursor_->empty()) {
        const auto [first, last] = cursor_->selection();
        log->withRecords(
                [&, first = first, last = last](std::span<const logview::EpochRecord> all) {
                    for (std::size_t i = first; i <= last && i < all.size(); ++i) {
                        const logview::EpochRecord &r = all[i];
                        if (r.hasPosition() && r.fixType() != FixType::None)
                            positions.add(r.lat, r.lon, std::nullopt, r.fixType());
                    }
                });
    }
    accuracy_->show(positions);
}

QString LogSummaryView::valueOf(const QString &name) const {
    for (int r = 0; r < table_->rowCount(); ++r)
        if (table_->item(r, 0)->text() == name) return table_->item(r, 1)->text();
    return {};
}

void LogSummaryView::addRow(const QString &name, const QString &value, const QColor &swatch) {
    const int r = table_->rowCount();
    table_->insertRow(r);
    auto *n = new QTableWidgetItem(name);
    if (swatch.isValid()) n->setData(Qt::DecorationRole, swatch);
    table_->setItem(r, 0, n);
    table_->setItem(r, 1, new QTableWidgetItem(value));
}

void LogSummaryView::reload() {
    table_->setRowCount(0);
    const logview::LogView *log = cursor_->log();
    if (!log || cursor_->empty()) {
        stats_ = {};
        title_->setText(log ? tr("Indexing…") : tr("No log open"));
        accuracyLater_->start();
        return;
    }
    const auto [first, last] = cursor_->selection();
    stats_ = log->stats(first, last, stationary_->isChecked());
    accuracyLater_->start();
    const auto a = log->epoch(first), b = log->epoch(last);
    title_->setText((cursor_->hasRange() ? tr("Selected range: epochs %1 to %2")
                                         : tr("Whole log: epochs %1 to %2"))
                            .arg(first)
                            .arg(last) +
                    (a && b ? QStringLiteral("\n%1 – %2")
                                      .arg(QString::fromStdString(logview::formatTime(*a)),
                                           QString::fromStdString(logview::formatTime(*b)))
                            : QString()));
    const auto &s = stats_;
    addRow(tr("Epochs"), QString::number(s.epochs));
    addRow(tr("Duration"), seconds(s.durationS));
    for (std::size_t f = 0; f < s.perFix.size(); ++f) {
        if (s.perFix[f] == 0) continue;
        const auto fix = static_cast<FixType>(f);
        addRow(tr("%1 (availability)").arg(style::fixTypeLabel(fix)),
               tr("%1 % (%2 epochs)").arg(s.availability(fix), 0, 'f', 1).arg(s.perFix[f]),
               style::fixTypeColor(fix));
    }
    addRow(tr("Time to first fix"), seconds(s.timeToFirstFixS));
    addRow(tr("Time to RTK fixed"), seconds(s.timeToRtkFixedS));
    addRow(tr("Data gaps"), s.gaps ? tr("%1, the longest %2 (before epoch %3)")
                                             .arg(s.gaps)
                                             .arg(seconds(s.longestGapS))
                                             .arg(s.longestGapEpoch)
                                   : tr("none"));
    addRow(tr("Time jumps"), QString::number(s.timeJumps));
    addRow(tr("Checksum errors"), QString::number(s.checksumErrors));
    addRow(tr("Epochs with junk"), QString::number(s.epochsWithJunk));
    addRow(tr("Positions"), s.stationaryOnly ? tr("%1 (standing still)").arg(s.positions)
                                             : QString::number(s.positions));
    addRow(tr("Mean position"),
           s.meanLat && s.meanLon ? tr("%1, %2").arg(fmt::latitude(s.meanLat, prefs_.coordinates),
                                                     fmt::longitude(s.meanLon, prefs_.coordinates))
                                  : fmt::dash());
    addRow(tr("Mean altitude"), fmt::length(s.meanAlt, 2, prefs_.units));
    addRow(tr("CEP50"), fmt::length(s.cep50, 3, prefs_.units));
    addRow(tr("CEP95"), fmt::length(s.cep95, 3, prefs_.units));
    addRow(tr("2DRMS"), fmt::length(s.drms2, 3, prefs_.units));
    addRow(tr("Max HDOP"),
           s.maxHdop ? tr("%1 (epoch %2)").arg(*s.maxHdop, 0, 'f', 1).arg(s.maxHdopEpoch)
                     : fmt::dash());
}

} // namespace gnss::ui
