#include "gui/main_window.h"

#include "common/app_transports.h"
#include "core/dialect_registry.h"
#include "gui/connection_bar.h"
#include "gui/corrections_controller.h"
#include "gui/log_viewer.h"
#include "gui/preferences_dialog.h"
#include "gui/receivers_strip.h"
#include "link/port_watcher.h"
#include "models/receiver_session.h"
#include "session/receiver_link.h"
#include "style/dark_palette.h"
#include "style/gnss_style.h"
#include "views/charts_view.h"
#include "views/console_view.h"
#include "views/sky_plot_view.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QStyleFactory>
#include <QTimer>

namespace gnss::app {

// How long a command's outcome stays in the status bar, and how often the bar is refreshed.
constexpr int kCommandMessageMs = 8000;
constexpr int kStatusRefreshMs = 500;

MainWindow::MainWindow(const DialectRegistry &registry, const link::TransportFactory &transports,
                       QSettings *settings, QWidget *parent)
    : QMainWindow(parent), registry_(registry), transports_(transports), settings_(settings) {
    setWindowTitle(tr("GNSS Workbench"));
    setObjectName("MainWindow");
    setDockNestingEnabled(true);
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks | GroupedDragging);
    if (settings_) prefs_ = Preferences::load(*settings_);
    startLanguage_ = prefs_.language;
    ports_ = new link::PortWatcher({}, this);
    ports_->start();
    // The first receiver; the docks show it. More come with Add receiver.
    current_ = newSession();
    // The open log's models: a session of its own, so that the receivers keep running (and
    // recording) while a log is studied.
    logSession_ = new ui::ReceiverSession(registry_, transports_, this);
    logSession_->setObjectName(QStringLiteral("logSession"));
    bar_ = new ConnectionBar(ports_, registry_, transports_.names(SourceSpec::Kind::Simulator),
                             this);
    addToolBar(Qt::TopToolBarArea, bar_);
    addToolBarBreak(Qt::TopToolBarArea);
    strip_ = new ReceiversStrip(this);
    addToolBar(Qt::TopToolBarArea, strip_);
    strip_->hide(); // shown while two or more receivers are open
    createLogViewer();
    createDocks();
    createMenus();
    createStatusBar();
    wireConnection();
    wireSession(current_);
    auto *statusTimer = new QTimer(this);
    statusTimer->setInterval(kStatusRefreshMs);
    connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
    statusTimer->start();
    // 1400x900 where the screen has room; on a smaller screen (a 1280x800 laptop) the whole
    // available area, maximised, never a window larger than the screen.
    const QSize preferred(1400, 900);
    const QRect avail = screen() ? screen()->availableGeometry() : QRect(QPoint(), preferred);
    resize(preferred.boundedTo(avail.size()));
    if (avail.width() < preferred.width() || avail.height() < preferred.height()) {
        move(avail.topLeft());
        setWindowState(windowState() | Qt::WindowMaximized);
    }
    defaultState_ = saveState();
    restoreLayout();
    putLogViewAway(); // a layout saved with a log open would show them empty
}

MainWindow::~MainWindow() {
    // The docks outlive this class's members (QWidget deletes its children later): their
    // destruction must not reach the dock table.
    for (QDockWidget *d : docks_.keys()) d->disconnect(this);
    stopLogSignalScan();
    // Closing the link fails a command still waiting for its answer; its report must not reach
    // a window half destroyed.
    for (ui::ReceiverSession *s : std::as_const(sessions_)) {
        s->link()->disconnect(this);
        s->link()->disconnectFromSource();
    }
}

void MainWindow::wireConnection() {
    connect(bar_, &ConnectionBar::connectRequested, this, [this](const SourceSpec &s) {
        if (!portTakenByAnother(s, current_)) connectReceiver(current_, s);
    });
    connect(bar_, &ConnectionBar::disconnectRequested, this,
            [this] { current_->link()->disconnectFromSource(); });
    connect(bar_, &ConnectionBar::addRequested, this, [this](const SourceSpec &s) {
        if (!portTakenByAnother(s, nullptr)) addReceiver(s);
    });
    connect(strip_, &ReceiversStrip::selectRequested, this,
            [this](int i) { selectReceiver(sessions_.value(i)); });
    connect(strip_, &ReceiversStrip::renameRequested, this,
            [this](int i) { renameReceiver(sessions_.value(i)); });
    connect(strip_, &ReceiversStrip::disconnectRequested, this, [this](int i) {
        if (ui::ReceiverSession *s = sessions_.value(i)) s->link()->disconnectFromSource();
    });
    // Queued: the chip whose menu asked is deleted with its receiver.
    connect(
            strip_, &ReceiversStrip::closeRequested, this,
            [this](int i) { closeReceiver(sessions_.value(i)); }, Qt::QueuedConnection);
}

void MainWindow::wireSession(ui::ReceiverSession *s) {
    session::ReceiverLink *lk = s->link();
    // The connection bar is about the selected receiver; the strip and status bar about all.
    connect(lk, &session::ReceiverLink::stateChanged, this, [this, s, lk] {
        if (s == current_) {
            const auto st = lk->state();
            bar_->setConnected(st != session::ReceiverLink::State::Disconnected &&
                               st != session::ReceiverLink::State::Failed);
            // The baud note belongs to a detection: gone with a source that had none.
            if (lk->detectedBaud() == 0 && st != session::ReceiverLink::State::Detecting &&
                st != session::ReceiverLink::State::Failed)
                bar_->setBaudNote({});
        }
        updateStatus();
    });
    connect(lk, &session::ReceiverLink::detectingRate, this, [this, s](int baud) {
        if (s == current_) bar_->setBaudNote(tr("trying %1…").arg(baud));
    });
    connect(lk, &session::ReceiverLink::detectionFinished, this, [this, s, lk](int baud) {
        if (s == current_)
            bar_->setBaudNote(baud > 0 ? tr("→ %1").arg(baud) : tr("not found"),
                              lk->detectionDetail());
    });
    // A device plugged in: a link waiting to reconnect tries at once.
    connect(ports_, &link::PortWatcher::portsChanged, lk, &session::ReceiverLink::retryNow);
    connect(lk, &session::ReceiverLink::commandFinished, this,
            [this, s](const QString &summary, bool ok) {
                QString text = ok ? summary : tr("Command: %1").arg(summary);
                if (sessions_.size() > 1) text = tr("%1: %2").arg(receiverLabel(s), text);
                statusBar()->showMessage(text, kCommandMessageMs);
            });
}

ui::ReceiverSession *MainWindow::session() const {
    return logViewer_ && logViewer_->isOpen() ? logSession_ : current_;
}

session::ReceiverLink *MainWindow::link() const {
    return current_->link();
}

ui::ReceiverStateModel *MainWindow::stateModel() const {
    return session()->state();
}

ui::SatelliteModel *MainWindow::satelliteModel() const {
    return session()->satellites();
}

QDockWidget *MainWindow::dock(const QString &objectName) const {
    return findChild<QDockWidget *>(objectName);
}

QStringList MainWindow::dockNames() const {
    QStringList names;
    for (const DockRow &row : dockRows()) names << QLatin1String(row.name);
    return names;
}

bool MainWindow::showDock(const QString &name) {
    const DockRow *row = findDockRow(name);
    QDockWidget *d = row ? dock(dockObjectName(*row)) : nullptr;
    if (!d) return false;
    d->show();
    d->raise();
    return true;
}

void MainWindow::createMenus() {
    QMenu *file = menuBar()->addMenu(tr("&File"));
    createLogMenu(file);
    file->addSeparator();
    recordAction_ = file->addAction(tr("&Record..."));
    recordAction_->setCheckable(true);
    recordAction_->setShortcut(QKeySequence(tr("Ctrl+R")));
    connect(recordAction_, &QAction::toggled, this, &MainWindow::toggleRecording);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *prefs = edit->addAction(tr("&Preferences..."), this, &MainWindow::openPreferences);
    prefs->setObjectName("preferencesAction");
    prefs->setShortcut(QKeySequence(tr("Ctrl+,")));
    prefs->setMenuRole(QAction::PreferencesRole);

    receiverMenu_ = menuBar()->addMenu(tr("&Receiver"));
    receiverMenu_->setObjectName("receiverMenu");
    receiverMenu_
            ->addAction(tr("&Connect"), this,
                        [this] { connectReceiver(current_, bar_->selection()); })
            ->setShortcut(QKeySequence(tr("Ctrl+K")));
    receiverMenu_
            ->addAction(tr("&Disconnect"), this,
                        [this] { current_->link()->disconnectFromSource(); })
            ->setShortcut(QKeySequence(tr("Ctrl+Shift+K")));
    receiverMenu_->addSeparator();
    // Several receivers: another one on the source chosen in the connection bar.
    QAction *add = receiverMenu_->addAction(tr("&Add Receiver"), this, [this] {
        const SourceSpec s = bar_->selection();
        if (!portTakenByAnother(s, nullptr)) addReceiver(s);
    });
    add->setObjectName("addReceiverAction");
    add->setShortcut(QKeySequence(tr("Ctrl+Shift+N")));
    receiverMenu_->addAction(tr("Re&name Receiver..."), this, [this] { renameReceiver(current_); });
    QAction *close = receiverMenu_->addAction(tr("C&lose Receiver"), this,
                                              [this] { closeReceiver(current_); });
    close->setObjectName("closeReceiverAction");
    receiverMenu_->addSeparator();
    rebuildReceiverActions(); // the receivers, Ctrl+1…9

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->setObjectName("viewMenu");
    for (const DockRow &row : dockRows()) {
        QDockWidget *d = dock(dockObjectName(row));
        viewMenu_->addAction(d->toggleViewAction());
        // A dock asked for comes to the front of its tab group, not behind the tab shown.
        connect(d->toggleViewAction(), &QAction::triggered, d, [d](bool shown) {
            if (shown) d->raise();
        });
    }
    // A second dock of a kind, pinned to the selected receiver (base and rover side by side).
    QMenu *more = viewMenu_->addMenu(tr("Another &dock for this receiver"));
    more->setObjectName("duplicateDockMenu");
    for (const DockRow &row : dockRows()) {
        if (row.log || row.window) continue;
        QAction *a = more->addAction(dockFullTitle(row), this, [this, &row] {
            if (QDockWidget *d = duplicateDock(QLatin1String(row.name), current_)) {
                d->show();
                d->raise();
            }
        });
        a->setObjectName(QStringLiteral("duplicate_%1").arg(QLatin1String(row.name)));
    }
    viewMenu_->addSeparator();
    QAction *tracks = viewMenu_->addAction(tr("Sky plot &tracks"));
    tracks->setObjectName("skyTracksAction");
    tracks->setCheckable(true);
    connect(tracks, &QAction::toggled, this, [this](bool on) {
        skyTracks_ = on;
        for (auto *sky : findChildren<ui::SkyPlotView *>()) sky->setShowTracks(on);
    });
    viewMenu_->addAction(tr("&Reset layout"), this, [this] { restoreState(defaultState_); });
    QMenu *theme = viewMenu_->addMenu(tr("T&heme"));
    auto *group = new QActionGroup(this);
    for (const auto &[id, label] :
         {std::pair{"system", QT_TR_NOOP("Follow the system")},
          std::pair{"light", QT_TR_NOOP("Light")}, std::pair{"dark", QT_TR_NOOP("Dark")}}) {
        QAction *a = theme->addAction(tr(label));
        a->setCheckable(true);
        a->setData(QString::fromLatin1(id));
        group->addAction(a);
        themeActions_ << a;
        connect(a, &QAction::triggered, this, [this, a] {
            Preferences p = prefs_;
            p.theme = a->data().toString();
            setPreferences(p);
        });
        a->setChecked(prefs_.theme == QLatin1String(id));
    }

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About GNSS Workbench"), this, [this] {
        QStringList families;
        for (const Dialect *d : registry_.dialects())
            families << QString::fromUtf8(d->displayName.data(), qsizetype(d->displayName.size()));
        QMessageBox::about(this, tr("About GNSS Workbench"),
                           tr("<b>GNSS Workbench</b> %1<br>Configure and monitor these receivers: "
                              "%2.")
                                   .arg(QApplication::applicationVersion(),
                                        families.join(QStringLiteral(", "))));
    });
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::createStatusBar() {
    auto make = [this](const char *name) {
        auto *l = new QLabel(this);
        l->setObjectName(QString::fromLatin1(name));
        statusBar()->addPermanentWidget(l);
        return l;
    };
    stateLabel_ = new QLabel(this);
    stateLabel_->setObjectName("connectionState");
    // Selectable: a failure can carry a command to run (the dialout group for a serial port).
    stateLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    statusBar()->addWidget(stateLabel_, 1);
    dialectLabel_ = make("statusDialect");
    rateLabel_ = make("statusRates");
    errorLabel_ = make("statusChecksumErrors");
    recordLabel_ = make("statusRecording");
    fixLabel_ = make("statusFix");
    fixLabel_->setAlignment(Qt::AlignCenter);
    fixLabel_->setMinimumWidth(90);
    updateStatus();
}

void MainWindow::updateStatus() {
    if (!stateLabel_) return;
    const bool log = logViewer_ && logViewer_->isOpen();
    ui::ReceiverSession *const shown = session();
    session::ReceiverLink *const lk = current_->link();
    QString state = log ? logViewer_->statusText() : lk->stateText();
    if (!log && sessions_.size() > 1) state = tr("%1: %2").arg(receiverLabel(current_), state);
    stateLabel_->setText(state);
    // The whole text too, for a message longer than the status bar shows.
    stateLabel_->setToolTip(log                               ? logViewer_->path()
                            : lk->detectionDetail().isEmpty() ? lk->stateText()
                                                              : lk->detectionDetail());
    const Dialect *d = log ? logViewer_->dialectAtCursor() : shown->dialect();
    const ReceiverIdentity &id = shown->state()->state().identity;
    QString who = d ? QString::fromLatin1(d->displayName.data(), int(d->displayName.size()))
                  : shown->counters().sentences > 0 ? tr("NMEA-0183 (no vendor sentences)")
                                                    : tr("dialect: —");
    if (!id.model.empty()) who = QString::fromStdString(id.vendor + " " + id.model);
    if (!id.firmware.empty()) who += tr(" (firmware %1)").arg(QString::fromStdString(id.firmware));
    dialectLabel_->setText(who);
    // A log's rates and errors are its statistics' business, not the status bar's.
    const auto &c = shown->counters();
    rateLabel_->setVisible(!log);
    errorLabel_->setVisible(!log);
    rateLabel_->setText(tr("%1 B/s · %2 sentences/s")
                                .arg(qRound(c.bytesPerSecond))
                                .arg(c.sentencesPerSecond, 0, 'f', 1));
    errorLabel_->setText(tr("checksum errors: %1").arg(c.checksumErrors));
    errorLabel_->setStyleSheet(
            c.checksumErrors ? QStringLiteral("color: %1;").arg(style::errorColor().name())
                             : QString());
    bool rec = false;
    for (ui::ReceiverSession *s : sessions_) rec = rec || s->link()->recording();
    recordLabel_->setText(rec ? tr("● REC") : QString());
    recordLabel_->setStyleSheet(
            rec ? QStringLiteral("color: %1; font-weight: bold;").arg(style::errorColor().name())
                : QString());
    // The badge is the live fix: none once the receiver is disconnected (the docks keep the last).
    const auto link = lk->state();
    const bool live = link != session::ReceiverLink::State::Disconnected &&
                      link != session::ReceiverLink::State::Failed;
    const bool any = (live || log) && shown->state()->epochCount() > 0;
    const FixType fix = any ? shown->state()->state().epoch.fix : FixType::None;
    fixLabel_->setText(any ? style::fixTypeLabel(fix) : tr("No fix"));
    fixLabel_->setStyleSheet(style::badgeCss(style::fixTypeColor(fix), 4, "1px 6px"));
    updateReceivers();
}

void MainWindow::toggleRecording(bool on) {
    if (!on) {
        for (ui::ReceiverSession *s : sessions_) s->link()->stopRecording();
        updateStatus();
        return;
    }
    bool started = false;
    if (sessions_.size() > 1) {
        // Every receiver, one file each in one folder, named after the receiver.
        const QString folder =
                QFileDialog::getExistingDirectory(this, tr("Record every receiver to"));
        QString why;
        started = !folder.isEmpty() && !recordAll(folder, &why).isEmpty();
        if (!folder.isEmpty() && !why.isEmpty()) QMessageBox::warning(this, tr("Record"), why);
    } else {
        const QString path = QFileDialog::getSaveFileName(
                this, tr("Record to"), QStringLiteral("receiver.nmea"), tr("NMEA logs (*.nmea)"));
        started = !path.isEmpty() && current_->link()->startRecording(path);
        if (!path.isEmpty() && !started)
            QMessageBox::warning(this, tr("Record"),
                                 tr("Cannot record to %1: connect to a receiver first, and "
                                    "check the folder is writable.")
                                         .arg(path));
    }
    if (!started) {
        QSignalBlocker block(recordAction_);
        recordAction_->setChecked(false);
    }
    updateStatus();
}

void MainWindow::applyTheme(const QString &theme) {
    if (theme == QLatin1String("system")) {
        QApplication::setPalette(QApplication::style()->standardPalette());
        return;
    }
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QPalette p;
    if (theme == QLatin1String("dark")) {
        p = style::darkPalette();
    } else {
        p = QApplication::style()->standardPalette();
    }
    QApplication::setPalette(p);
}

void MainWindow::saveLayout() {
    if (!settings_) return;
    settings_->setValue("window/geometry", saveGeometry());
    settings_->setValue("window/state", saveState());
    settings_->setValue("view/skyTracks", skyTracks_);
    if (auto *charts = qobject_cast<ui::ChartsView *>(dock("chartsDock")->widget())) {
        settings_->setValue("view/chartSeries", charts->checkedSeries());
        settings_->setValue("view/chartWindowMinutes", charts->windowMinutes());
    }
    if (auto *console = qobject_cast<ui::ConsoleView *>(dock("consoleDock")->widget()))
        consoleHistory_ = console->history();
    settings_->setValue("console/history", consoleHistory_);
    const SourceSpec s = current_->link()->source();
    if (s.valid()) settings_->setValue("connection/last", s.toString());
    saveReceivers();
}

void MainWindow::restoreLayout() {
    if (!settings_) return;
    restoreGeometry(settings_->value("window/geometry").toByteArray());
    if (!restoreState(settings_->value("window/state").toByteArray())) {
        // The first start: the fix's group has 55% of the width and the sky's the rest,
        // whatever their views' size hints ask, so that the tabs beside the fix stay whole.
        QTimer::singleShot(0, this, [this] {
            if (isVisible())
                resizeDocks({dock("skyDock"), dock("fixDock")},
                            {width() * 45 / 100, width() * 55 / 100}, Qt::Horizontal);
        });
    }
    if (auto *tracks = findChild<QAction *>("skyTracksAction"))
        tracks->setChecked(settings_->value("view/skyTracks", false).toBool());
    if (auto *charts = qobject_cast<ui::ChartsView *>(dock("chartsDock")->widget())) {
        if (settings_->contains("view/chartSeries"))
            charts->setCheckedSeries(settings_->value("view/chartSeries").toStringList());
        charts->setWindowMinutes(
                settings_->value("view/chartWindowMinutes", charts->windowMinutes()).toInt());
    }
    consoleHistory_ = settings_->value("console/history").toStringList();
    if (auto *console = qobject_cast<ui::ConsoleView *>(dock("consoleDock")->widget()))
        console->setHistory(consoleHistory_);
    if (prefs_.theme != QLatin1String("system")) applyTheme(prefs_.theme);
    for (ui::ReceiverSession *s : sessions_) s->link()->setBaudCandidates(prefs_.detectionBauds);
    emit displayPrefsChanged(prefs_.display);
}

void MainWindow::setPreferences(const Preferences &p) {
    const Preferences before = prefs_;
    prefs_ = p;
    if (settings_) p.save(*settings_);
    if (p.theme != before.theme) applyTheme(p.theme);
    for (QAction *a : themeActions_) a->setChecked(a->data().toString() == p.theme);
    for (ui::ReceiverSession *s : sessions_) s->link()->setBaudCandidates(p.detectionBauds);
    if (!(p.display == before.display)) emit displayPrefsChanged(p.display);
    if (p.language != startLanguage_)
        statusBar()->showMessage(
                tr("The new language is used from the next start of GNSS Workbench."), 10000);
}

void MainWindow::openPreferences() {
    auto *dialog = new PreferencesDialog(prefs_, startLanguage_, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { setPreferences(dialog->preferences()); });
    dialog->open();
}

void MainWindow::closeEvent(QCloseEvent *e) {
    saveLayout();
    for (ui::ReceiverSession *s : sessions_) s->link()->disconnectFromSource(); // flushes
    QMainWindow::closeEvent(e);
}

} // namespace gnss::app
