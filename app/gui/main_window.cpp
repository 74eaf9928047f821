#include "gui/main_window.h"

#include "common/app_transports.h"
#include "core/dialect_registry.h"
#include "gui/connection_bar.h"
#include "gui/corrections_controller.h"
#include "gui/log_viewer.h"
#include "gui/preferences_dialog.h"
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
    // One receiver for now; the docks show it.
    session_ = new ui::ReceiverSession(registry_, transports_, this);
    session_->setObjectName(QStringLiteral("session1"));
    sessions_ << session_;
    link_ = session_->link();
    corrections_ = new CorrectionsController(settings_, this);
    ports_ = new link::PortWatcher({}, this);
    ports_->start();
    bar_ = new ConnectionBar(ports_, registry_, transports_.names(SourceSpec::Kind::Simulator),
                             this);
    addToolBar(Qt::TopToolBarArea, bar_);
    createLogViewer();
    createDocks();
    wireLogConsole();
    createMenus();
    createStatusBar();
    wireConnection();
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
    // Closing the link fails a command still waiting for its answer; its report must not reach
    // a window half destroyed.
    for (ui::ReceiverSession *s : sessions_) {
        s->link()->disconnect(this);
        s->link()->disconnectFromSource();
    }
}

void MainWindow::wireConnection() {
    connect(bar_, &ConnectionBar::connectRequested, this,
            [this](const SourceSpec &s) { link_->connectTo(s); });
    connect(bar_, &ConnectionBar::disconnectRequested, link_,
            &session::ReceiverLink::disconnectFromSource);
    connect(link_, &session::ReceiverLink::stateChanged, this, [this] {
        const auto s = link_->state();
        bar_->setConnected(s != session::ReceiverLink::State::Disconnected &&
                           s != session::ReceiverLink::State::Failed);
        // The baud note belongs to a detection: gone with a source that had none.
        if (link_->detectedBaud() == 0 && s != session::ReceiverLink::State::Detecting &&
            s != session::ReceiverLink::State::Failed)
            bar_->setBaudNote({});
        updateStatus();
    });
    connect(link_, &session::ReceiverLink::detectingRate, this,
            [this](int baud) { bar_->setBaudNote(tr("trying %1…").arg(baud)); });
    connect(link_, &session::ReceiverLink::detectionFinished, this, [this](int baud) {
        bar_->setBaudNote(baud > 0 ? tr("→ %1").arg(baud) : tr("not found"),
                          link_->detectionDetail());
    });
    // A device plugged in: a link waiting to reconnect tries at once.
    connect(ports_, &link::PortWatcher::portsChanged, link_, &session::ReceiverLink::retryNow);
    connect(link_, &session::ReceiverLink::commandFinished, this,
            [this](const QString &summary, bool ok) {
                statusBar()->showMessage(ok ? summary : tr("Command: %1").arg(summary),
                                         kCommandMessageMs);
            });
}

session::ReceiverLink *MainWindow::link() const {
    return link_;
}

ui::ReceiverStateModel *MainWindow::stateModel() const {
    return session_->state();
}

ui::SatelliteModel *MainWindow::satelliteModel() const {
    return session_->satellites();
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

    QMenu *receiver = menuBar()->addMenu(tr("&Receiver"));
    receiver->setObjectName("receiverMenu");
    receiver->addAction(tr("&Connect"), this, [this] { link_->connectTo(bar_->selection()); })
            ->setShortcut(QKeySequence(tr("Ctrl+K")));
    receiver->addAction(tr("&Disconnect"), link_, &session::ReceiverLink::disconnectFromSource)
            ->setShortcut(QKeySequence(tr("Ctrl+Shift+K")));

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->setObjectName("viewMenu");
    for (const DockRow &row : dockRows())
        viewMenu_->addAction(dock(dockObjectName(row))->toggleViewAction());
    viewMenu_->addSeparator();
    QAction *tracks = viewMenu_->addAction(tr("Sky plot &tracks"));
    tracks->setCheckable(true);
    connect(tracks, &QAction::toggled, sky_, &ui::SkyPlotView::setShowTracks);
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
    const bool log = logViewer_ && logViewer_->isOpen();
    stateLabel_->setText(log ? logViewer_->statusText() : link_->stateText());
    // The whole text too, for a message longer than the status bar shows.
    stateLabel_->setToolTip(log                                  ? logViewer_->path()
                            : link_->detectionDetail().isEmpty() ? link_->stateText()
                                                                 : link_->detectionDetail());
    const Dialect *d = log ? logViewer_->dialectAtCursor() : session_->dialect();
    const ReceiverIdentity &id = session_->state()->state().identity;
    QString who = d ? QString::fromLatin1(d->displayName.data(), int(d->displayName.size()))
                  : session_->counters().sentences > 0 ? tr("NMEA-0183 (no vendor sentences)")
                                                       : tr("dialect: —");
    if (!id.model.empty()) who = QString::fromStdString(id.vendor + " " + id.model);
    if (!id.firmware.empty()) who += tr(" (firmware %1)").arg(QString::fromStdString(id.firmware));
    dialectLabel_->setText(who);
    // A log's rates and errors are its statistics' business, not the status bar's.
    const auto &c = session_->counters();
    rateLabel_->setVisible(!log);
    errorLabel_->setVisible(!log);
    rateLabel_->setText(tr("%1 B/s · %2 sentences/s")
                                .arg(qRound(c.bytesPerSecond))
                                .arg(c.sentencesPerSecond, 0, 'f', 1));
    errorLabel_->setText(tr("checksum errors: %1").arg(c.checksumErrors));
    errorLabel_->setStyleSheet(
            c.checksumErrors ? QStringLiteral("color: %1;").arg(style::errorColor().name())
                             : QString());
    const bool rec = link_->recording();
    recordLabel_->setText(rec ? tr("● REC") : QString());
    recordLabel_->setStyleSheet(
            rec ? QStringLiteral("color: %1; font-weight: bold;").arg(style::errorColor().name())
                : QString());
    // The badge is the live fix: none once the receiver is disconnected (the docks keep the last).
    const auto link = link_->state();
    const bool live = link != session::ReceiverLink::State::Disconnected &&
                      link != session::ReceiverLink::State::Failed;
    const bool any = (live || log) && session_->state()->epochCount() > 0;
    const FixType fix = any ? session_->state()->state().epoch.fix : FixType::None;
    fixLabel_->setText(any ? style::fixTypeLabel(fix) : tr("No fix"));
    fixLabel_->setStyleSheet(style::badgeCss(style::fixTypeColor(fix), 4, "1px 6px"));
}

void MainWindow::toggleRecording(bool on) {
    if (!on) {
        link_->stopRecording();
        updateStatus();
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
            this, tr("Record to"), QStringLiteral("receiver.nmea"), tr("NMEA logs (*.nmea)"));
    if (path.isEmpty() || !link_->startRecording(path)) {
        if (!path.isEmpty())
            QMessageBox::warning(this, tr("Record"),
                                 tr("Cannot record to %1: connect to a receiver first, and "
                                    "check the folder is writable.")
                                         .arg(path));
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
    settings_->setValue("view/skyTracks", sky_->showTracks());
    settings_->setValue("view/chartSeries", charts_->checkedSeries());
    settings_->setValue("view/chartWindowMinutes", charts_->windowMinutes());
    settings_->setValue("console/history", consoleView_->history());
    const SourceSpec s = link_->source();
    if (s.valid()) settings_->setValue("connection/last", s.toString());
}

void MainWindow::restoreLayout() {
    if (!settings_) return;
    restoreGeometry(settings_->value("window/geometry").toByteArray());
    restoreState(settings_->value("window/state").toByteArray());
    sky_->setShowTracks(settings_->value("view/skyTracks", false).toBool());
    if (settings_->contains("view/chartSeries"))
        charts_->setCheckedSeries(settings_->value("view/chartSeries").toStringList());
    charts_->setWindowMinutes(
            settings_->value("view/chartWindowMinutes", charts_->windowMinutes()).toInt());
    consoleView_->setHistory(settings_->value("console/history").toStringList());
    if (prefs_.theme != QLatin1String("system")) applyTheme(prefs_.theme);
    link_->setBaudCandidates(prefs_.detectionBauds);
    emit displayPrefsChanged(prefs_.display);
}

void MainWindow::setPreferences(const Preferences &p) {
    const Preferences before = prefs_;
    prefs_ = p;
    if (settings_) p.save(*settings_);
    if (p.theme != before.theme) applyTheme(p.theme);
    for (QAction *a : themeActions_) a->setChecked(a->data().toString() == p.theme);
    link_->setBaudCandidates(p.detectionBauds);
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

void MainWindow::connectAtStart(const SourceSpec &spec) {
    SourceSpec s = spec;
    if (!s.valid() && settings_)
        s = SourceSpec::fromString(settings_->value("connection/last").toString());
    // A first start: the first family the simulator plays.
    const QStringList simulated = transports_.names(SourceSpec::Kind::Simulator);
    if (!s.valid() && !simulated.isEmpty())
        s = SourceSpec{SourceSpec::Kind::Simulator, simulated.front()};
    bar_->select(s);
    link_->connectTo(s);
}

void MainWindow::closeEvent(QCloseEvent *e) {
    saveLayout();
    link_->disconnectFromSource(); // flushes a recording
    QMainWindow::closeEvent(e);
}

} // namespace gnss::app
