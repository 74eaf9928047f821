// MainWindow's offline log viewer: the timeline under the views, the log's own docks (events,
// range statistics, whole-log charts, track), File → Open Log / Open Recent / Export / Close,
// drag and drop. The live docks are the same ones: LogViewer publishes the state at the cursor
// into their models.
#include "gui/log_player.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "gui/play_out_dialog.h"
#include "logview/log_view.h"
#include "logview/timeline_panel.h"
#include "logview/timeline_strip.h"
#include "models/receiver_session.h"
#include "models/signal_history_model.h"
#include "session/receiver_link.h"
#include "views/console_view.h"

#include <QAction>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QThread>
#include <QTimer>
#include <QToolBar>

namespace gnss::app {

namespace {
constexpr int kRecentLogs = 8;
const char *const kRecentKey = "logview/recent";
// The first live dock of a log dock's tab group (the dock table's rows), which it joins.
QString groupLeader(const DockRow &logRow) {
    for (const DockRow &r : dockRows())
        if (!r.log && r.tabGroup && logRow.tabGroup && qstrcmp(r.tabGroup, logRow.tabGroup) == 0)
            return dockObjectName(r);
    return {};
}
} // namespace

void MainWindow::createLogViewer() {
    logViewer_ = new LogViewer(registry_, logSession_->models(), this);
    logPlayer_ = new LogPlayer(this);
    ui::LogCursor *cursor = logViewer_->cursor();
    auto *panel = new ui::TimelinePanel(cursor, this);
    timelineBar_ = new QToolBar(tr("Timeline"), this);
    timelineBar_->setObjectName("timelineBar");
    timelineBar_->setMovable(false);
    timelineBar_->setAllowedAreas(Qt::BottomToolBarArea | Qt::TopToolBarArea);
    timelineBar_->addWidget(panel);
    timelineBar_->toggleViewAction()->setText(tr("Log timeline"));
    addToolBar(Qt::BottomToolBarArea, timelineBar_);
    timelineBar_->hide();
    connect(panel, &ui::TimelinePanel::playRequested, logViewer_, &LogViewer::setPlaying);
    connect(logViewer_, &LogViewer::playingChanged, panel, &ui::TimelinePanel::setPlaying);
    connect(panel, &ui::TimelinePanel::speedChanged, logViewer_, &LogViewer::setSpeed);
    connect(panel, &ui::TimelinePanel::followRequested, logViewer_, &LogViewer::setFollowing);
    connect(logViewer_, &LogViewer::progress, panel->strip(), &ui::TimelineStrip::setProgress);
    connect(logViewer_, &LogViewer::progress, panel, &ui::TimelinePanel::setIndexing);
    connect(panel, &ui::TimelinePanel::cancelRequested, logViewer_, &LogViewer::cancelIndexing);
    connect(logViewer_, &LogViewer::statusChanged, this, &MainWindow::updateStatus);
    connect(logViewer_, &LogViewer::exportFinished, this,
            [this](bool, const QString &message) { statusBar()->showMessage(message, 10000); });

    logViewer_->lines()->setTimeZone(prefs_.display.time);
    connect(this, &MainWindow::displayPrefsChanged, logViewer_->lines(),
            [this](const ui::DisplayPrefs &p) { logViewer_->lines()->setTimeZone(p.time); });
    // The log's signal history is the selected range's (the whole log's without one), scanned on
    // a worker once the log is indexed and again when the range settles (the cursor's moves are
    // not new epochs).
    logSession_->signalHistory()->setHistory(SignalHistory(0));
    connect(logViewer_, &LogViewer::indexed, this, [this] {
        if (!logSignalsScanned_) scanLogSignals();
    });
    auto *rescan = new QTimer(this);
    rescan->setSingleShot(true);
    rescan->setInterval(300); // a range being dragged is scanned once it stops
    connect(rescan, &QTimer::timeout, this, [this] {
        if (logSignalsScanned_) scanLogSignals();
    });
    connect(logViewer_->cursor(), &ui::LogCursor::rangeChanged, rescan,
            qOverload<>(&QTimer::start));
    setAcceptDrops(true);
}

void MainWindow::scanLogSignals() {
    stopLogSignalScan();
    const logview::LogView *view = logViewer_->view();
    const ui::LogCursor *cursor = logViewer_->cursor();
    if (!view || cursor->empty()) return;
    logSignalsScanned_ = true;
    const auto [firstEpoch, lastEpoch] = cursor->selection();
    // About two thousand samples per signal over the range, one a second at most.
    const auto first = view->epoch(firstEpoch), last = view->epoch(lastEpoch);
    const bool timed =
            first && last && first->utcMs != logview::kNoTime && last->utcMs != logview::kNoTime;
    const std::int64_t step =
            std::max<std::int64_t>(1000, timed ? (last->utcMs - first->utcMs) / 2000 : 0);
    const logview::LogView::Slice slice = view->slice(firstEpoch, lastEpoch);
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    logScanCancel_ = cancel;
    QPointer<ui::SignalHistoryModel> target = logSession_->signalHistory();
    const DialectRegistry *registry = &registry_;
    logScan_ = QThread::create([slice, step, cancel, target, registry] {
        SignalHistory h = historyOfLog(slice.bytes, *registry, step, slice.dialect, cancel.get());
        if (cancel->load()) return;
        QMetaObject::invokeMethod(
                target.data(),
                [target, h]() {
                    if (target) target->setHistory(h);
                },
                Qt::QueuedConnection);
    });
    logScan_->start(QThread::LowPriority);
}

void MainWindow::stopLogSignalScan() {
    if (!logScan_) return;
    *logScanCancel_ = true;
    logScan_->wait(); // it stops within a megabyte
    delete logScan_;
    logScan_ = nullptr;
}

void MainWindow::wireLogConsole(ui::ConsoleView *view) {
    // The console shows the log's own lines while a log is open: filtered by the model (a whole
    // log, on a worker), the cursor's line kept in view, a line double-clicked is its moment.
    ui::LogLinesModel *lines = logViewer_->lines();
    connect(view, &ui::ConsoleView::filterChanged, lines, &ui::LogLinesModel::setFilter);
    connect(lines, &ui::LogLinesModel::cursorRowChanged, view, &ui::ConsoleView::showRow);
    connect(lines, &ui::LogLinesModel::noteChanged, view, &ui::ConsoleView::setNote);
    view->showLog(lines, [this] { return logViewer_->lines()->bytesBeforeCursor(8192); });
    connect(view, &ui::ConsoleView::lineActivated, this, [this, lines](int row) {
        const auto offset = lines->offsetOfRow(row);
        const logview::LogView *view = logViewer_->view();
        const auto epoch = offset && view ? view->epochAtOffset(*offset) : std::nullopt;
        if (epoch && !logViewer_->cursor()->empty()) logViewer_->cursor()->seek(*epoch, true);
    });
}

void MainWindow::createLogMenu(QMenu *file) {
    QAction *open = file->addAction(tr("&Open Log..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
                this, tr("Open Log"), {},
                tr("NMEA logs (*.nmea *.log *.txt *.gz *.nmea.gz);;All files (*)"));
        if (!path.isEmpty()) openLog(path);
    });
    open->setObjectName("openLogAction");
    open->setShortcut(QKeySequence::Open);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    recentMenu_->setObjectName("recentLogsMenu");
    updateRecentMenu();
    exportAction_ = file->addAction(tr("&Export Log..."), this, &MainWindow::exportLog);
    exportAction_->setObjectName("exportLogAction");
    exportAction_->setShortcut(QKeySequence(tr("Ctrl+E")));
    exportAction_->setEnabled(false);
    playOutAction_ = file->addAction(tr("&Play Out..."), this, &MainWindow::openPlayOut);
    playOutAction_->setObjectName("playOutAction");
    playOutAction_->setEnabled(false);
    closeLogAction_ = file->addAction(tr("&Close Log"), this, &MainWindow::closeLog);
    closeLogAction_->setObjectName("closeLogAction");
    closeLogAction_->setShortcut(QKeySequence::Close);
    closeLogAction_->setEnabled(false);
    // A start time the log does not hold: said by the Go to box and in the status bar.
    connect(logViewer_, &LogViewer::startRefused, this, [this](const QString &why) {
        if (auto *panel = timelineBar_->findChild<ui::TimelinePanel *>()) panel->showMessage(why);
        statusBar()->showMessage(tr("--at: %1").arg(why), 15000);
    });
    connect(logViewer_, &LogViewer::indexed, this, [this] {
        exportAction_->setEnabled(logViewer_->isOpen() && !logViewer_->cursor()->empty());
        playOutAction_->setEnabled(exportAction_->isEnabled());
    });
}

QStringList MainWindow::recentLogs() const {
    return settings_ ? settings_->value(kRecentKey).toStringList() : QStringList();
}

void MainWindow::rememberLog(const QString &path) {
    if (!settings_) return;
    QStringList list = recentLogs();
    const QString abs = QFileInfo(path).absoluteFilePath();
    list.removeAll(abs);
    list.prepend(abs);
    while (list.size() > kRecentLogs) list.removeLast();
    settings_->setValue(kRecentKey, list);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    if (!recentMenu_) return;
    recentMenu_->clear();
    const QStringList list = recentLogs();
    for (const QString &p : list)
        recentMenu_->addAction(QFileInfo(p).fileName(), this, [this, p] { openLog(p); })
                ->setToolTip(p);
    recentMenu_->setEnabled(!list.isEmpty());
    if (!list.isEmpty()) {
        recentMenu_->addSeparator();
        recentMenu_->addAction(tr("Clear the list"), this, [this] {
            if (settings_) settings_->remove(kRecentKey);
            updateRecentMenu();
        });
    }
}

void MainWindow::openLog(const QString &path, const QString &at) {
    // The receivers keep running (and recording); the docks that follow the selection show the
    // log, those pinned to a receiver go on showing it.
    // Before open(): a small log is indexed by the time open() returns, and the `indexed` it
    // emits then enables these; disabling them after would leave Export greyed on a ready log.
    exportAction_->setEnabled(false);
    playOutAction_->setEnabled(false);
    const bool wasOpen = logViewer_->isOpen();
    stopLogSignalScan(); // before the old log's mapping goes
    logSignalsScanned_ = false;
    logSession_->signalHistory()->setHistory(SignalHistory(0));
    logViewer_->open(path, at);
    if (wasOpen) { // the consoles on the log show the new one's lines
        for (auto it = docks_.cbegin(); it != docks_.cend(); ++it)
            if (auto *view = qobject_cast<ui::ConsoleView *>(it.key()->widget());
                view && it->shown == logSession_)
                view->showLog(logViewer_->lines(),
                              [this] { return logViewer_->lines()->bytesBeforeCursor(8192); });
    }
    rebindFollowingDocks();
    rememberLog(path);
    timelineBar_->show();
    // The transport's keys (Space, arrows) act at once, not in the source box's text.
    if (auto *strip = timelineBar_->findChild<ui::TimelineStrip *>()) strip->setFocus();
    closeLogAction_->setEnabled(true);
    setWindowTitle(tr("%1 — GNSS Workbench").arg(QFileInfo(path).fileName()));
    if (!logDocksShown_) {
        // The first log of the session brings its docks forward, beside the live ones.
        logDocksShown_ = true;
        for (const DockRow &row : dockRows()) {
            if (!row.log) continue;
            QDockWidget *d = dock(dockObjectName(row));
            QDockWidget *b = dock(groupLeader(row));
            // Beside a live dock the first time; where the user left it after that.
            if (!logDocksPlaced_ && b && b->isVisible() && !d->isVisible()) tabifyDockWidget(b, d);
            d->show();
        }
        for (const DockRow &row : dockRows())
            if (row.log && row.front) dock(dockObjectName(row))->raise();
        logDocksPlaced_ = true;
    }
    updateStatus();
    // The docks' new views laid out now, not at the next pass of the event loop.
    layout()->activate();
}

// The log's docks and timeline belong to an open log: without one they would only say "no log
// open", taking half the window from the live views. Put away at start (a layout saved with a log
// open shows them) and when the log closes; a hidden dock keeps its place, and the next log shows
// them there.
void MainWindow::putLogViewAway() {
    // Each log dock's live neighbour is brought back to the front of their tab group (Qt would
    // show the next tab, the deviation rather than the sky plot).
    for (const DockRow &row : dockRows()) {
        if (!row.log) continue;
        QDockWidget *d = dock(dockObjectName(row));
        QDockWidget *live = dock(groupLeader(row));
        const bool tabbed = live && tabifiedDockWidgets(d).contains(live);
        if (!d->isHidden()) logDocksPlaced_ = true;
        d->hide();
        if (tabbed && !live->isHidden()) live->raise();
    }
    timelineBar_->hide();
    logDocksShown_ = false;
}

void MainWindow::closeLog() {
    if (!logViewer_->isOpen()) return;
    stopLogSignalScan();
    logViewer_->close();
    rebindFollowingDocks(); // the selected receiver again
    putLogViewAway();
    closeLogAction_->setEnabled(false);
    exportAction_->setEnabled(false);
    playOutAction_->setEnabled(false);
    setWindowTitle(tr("GNSS Workbench"));
    updateStatus();
}

void MainWindow::exportLog() {
    if (!logViewer_->isOpen() || logViewer_->cursor()->empty()) return;
    const auto [first, last] = logViewer_->cursor()->selection();
    const QString base = QFileInfo(logViewer_->path()).completeBaseName();
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
            this,
            logViewer_->cursor()->hasRange() ? tr("Export epochs %1 to %2").arg(first).arg(last)
                                             : tr("Export the whole log"),
            base + QStringLiteral(".gpx"),
            tr("GPX track (*.gpx);;KML, coloured by fix (*.kml);;CSV, one row per epoch "
               "(*.csv);;NMEA, the bytes as in the file (*.nmea);;Statistics (*.json)"),
            &filter);
    if (path.isEmpty()) return;
    QString why;
    const auto format = LogViewer::formatOfSuffix(QFileInfo(path).suffix());
    if (!format)
        why = tr("name the file .gpx, .kml, .csv, .nmea or .json: the suffix says the format");
    else if (logViewer_->exportTo(*format, path, &why))
        statusBar()->showMessage(tr("Exporting to %1…").arg(path));
    if (!why.isEmpty()) statusBar()->showMessage(tr("Not exported: %1").arg(why), 10000);
}

void MainWindow::openPlayOut() {
    auto *dialog = findChild<PlayOutDialog *>();
    if (!dialog) dialog = new PlayOutDialog(logViewer_, logPlayer_, this);
    dialog->show();
    dialog->raise();
}

void MainWindow::dragEnterEvent(QDragEnterEvent *e) {
    const auto urls = e->mimeData()->urls();
    if (!urls.isEmpty() && urls.constFirst().isLocalFile()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *e) {
    const auto urls = e->mimeData()->urls();
    if (urls.isEmpty() || !urls.constFirst().isLocalFile()) return;
    openLog(urls.constFirst().toLocalFile());
    e->acceptProposedAction();
}

} // namespace gnss::app
