#include "main_window.h"

#include "app_transports.h"
#include "connection_bar.h"
#include "connection_controller.h"
#include "core/dialect_registry.h"
#include "corrections_controller.h"
#include "link/port_watcher.h"
#include "log_viewer.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "preferences_dialog.h"
#include "settings/settings_view.h"
#include "style/dark_palette.h"
#include "style/gnss_style.h"
#include "views/attitude_view.h"
#include "views/charts_view.h"
#include "views/console_view.h"
#include "views/corrections_view.h"
#include "views/deviation_view.h"
#include "views/fix_view.h"
#include "views/message_stats_view.h"
#include "views/receiver_info_view.h"
#include "views/rtk_view.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"
#include "widgets/fitted_columns.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QStyleFactory>
#include <QTableView>
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
    createModels();
    ports_ = new link::PortWatcher({}, this);
    ports_->start();
    bar_ = new ConnectionBar(ports_, registry_, simulatedDialects(registry_), this);
    addToolBar(Qt::TopToolBarArea, bar_);
    createDocks();
    createMenus();
    createStatusBar();
    connect(bar_, &ConnectionBar::connectRequested, this,
            [this](const SourceSpec &s) { controller_->connectTo(s); });
    connect(bar_, &ConnectionBar::disconnectRequested, controller_,
            &ConnectionController::disconnectFromSource);
    connect(controller_, &ConnectionController::stateChanged, this, [this] {
        const auto s = controller_->state();
        bar_->setConnected(s != ConnectionController::State::Disconnected &&
                           s != ConnectionController::State::Failed);
        // The baud note belongs to a detection: gone with a source that had none.
        if (controller_->detectedBaud() == 0 && s != ConnectionController::State::Detecting &&
            s != ConnectionController::State::Failed)
            bar_->setBaudNote({});
        // A link that takes no commands (gpsd, a replay): the send box says why it is off.
        consoleView_->setSendRefusal(controller_->sendRefusal());
        updateStatus();
    });
    connect(controller_, &ConnectionController::detectingRate, this,
            [this](int baud) { bar_->setBaudNote(tr("trying %1…").arg(baud)); });
    connect(controller_, &ConnectionController::detectionFinished, this, [this](int baud) {
        bar_->setBaudNote(baud > 0 ? tr("→ %1").arg(baud) : tr("not found"),
                          controller_->detectionDetail());
    });
    // A device plugged in: a link waiting to reconnect tries at once.
    connect(ports_, &link::PortWatcher::portsChanged, controller_, &ConnectionController::retryNow);
    connect(controller_, &ConnectionController::commandFinished, this,
            [this](const QString &summary, bool ok) {
                statusBar()->showMessage(ok ? summary : tr("Command: %1").arg(summary),
                                         kCommandMessageMs);
            });
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
    controller_->disconnect(this);
    controller_->disconnectFromSource();
}

void MainWindow::createModels() {
    stateModel_ = new ui::ReceiverStateModel(this);
    satellites_ = new ui::SatelliteModel(this);
    messages_ = new ui::MessageStatsModel(this);
    console_ = new ui::ConsoleModel(this);
    session_ = new ui::ReceiverSession(registry_, {stateModel_, satellites_, messages_, console_},
                                       this);
    controller_ = new ConnectionController(registry_, transports_, session_, this);
}

QDockWidget *MainWindow::addDock(QWidget *w, const QString &title, const QString &fullTitle,
                                 const QString &objectName, Qt::DockWidgetArea area) {
    // Tabs show the short title (whole even at 1280 px); the View menu the full one.
    auto *d = new QDockWidget(title, this);
    d->setObjectName(objectName);
    d->setWidget(w);
    d->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                   QDockWidget::DockWidgetFloatable);
    d->toggleViewAction()->setText(fullTitle);
    d->toggleViewAction()->setToolTip(fullTitle);
    addDockWidget(area, d);
    return d;
}

QDockWidget *MainWindow::dock(const QString &objectName) const {
    return findChild<QDockWidget *>(objectName);
}

QStringList MainWindow::dockNames() const {
    QStringList names;
    for (const QDockWidget *d : findChildren<QDockWidget *>()) {
        QString n = d->objectName();
        if (n.endsWith(QLatin1String("Dock"))) n.chop(4);
        names << n;
    }
    return names;
}

bool MainWindow::showDock(const QString &name) {
    QDockWidget *d = dock(name + QLatin1String("Dock"));
    if (!d) return false;
    d->show();
    d->raise();
    return true;
}

void MainWindow::createDocks() {
    sky_ = new ui::SkyPlotView(satellites_, this);
    auto *skyDock =
            addDock(sky_, tr("Sky plot"), tr("Sky plot"), "skyDock", Qt::LeftDockWidgetArea);
    auto *fixView = new ui::FixView(stateModel_, this);
    auto *fixDock =
            addDock(fixView, tr("Fix"), tr("Fix and position"), "fixDock", Qt::RightDockWidgetArea);
    // Units, coordinate format and time zone (Preferences) reach every view that shows them.
    connect(this, &MainWindow::displayPrefsChanged, fixView, &ui::FixView::setDisplayPrefs);
    connect(fixView, &ui::FixView::coordinateFormatChosen, this, [this](ui::CoordinateFormat f) {
        Preferences p = prefs_;
        p.display.coordinates = f;
        setPreferences(p);
    });
    connect(this, &MainWindow::displayPrefsChanged, console_, [this](const ui::DisplayPrefs &p) {
        console_->setTimeZone(p.time);
        if (logViewer_) logViewer_->lines()->setTimeZone(p.time);
        messages_->setTimeZone(p.time);
    });
    auto *signalDock = addDock(new ui::SignalLevelsView(satellites_, this), tr("Signal levels"),
                               tr("Signal levels"), "signalDock", Qt::BottomDockWidgetArea);
    auto *table = new QTableView(this);
    table->setObjectName("satelliteTable");
    table->setModel(satellites_);
    table->verticalHeader()->hide();
    // Rewritten whole at every epoch: measured when satellites come or go and once a second.
    new ui::FittedColumns(table, table->horizontalHeader());
    auto *satDock = addDock(table, tr("Satellites"), tr("Satellites"), "satellitesDock",
                            Qt::RightDockWidgetArea);
    consoleView_ = new ui::ConsoleView(console_, this);
    auto *consoleDock = addDock(consoleView_, tr("Console"), tr("Console"), "consoleDock",
                                Qt::BottomDockWidgetArea);
    auto *statsDock = addDock(new ui::MessageStatsView(messages_, this), tr("Statistics"),
                              tr("Message statistics"), "statsDock", Qt::BottomDockWidgetArea);
    auto *infoDock = addDock(new ui::ReceiverInfoView(stateModel_, this), tr("Receiver"),
                             tr("Receiver information"), "infoDock", Qt::RightDockWidgetArea);
    rtk_ = new ui::RtkView(stateModel_, this);
    connect(this, &MainWindow::displayPrefsChanged, rtk_, &ui::RtkView::setDisplayPrefs);
    auto *rtkDock = addDock(rtk_, tr("RTK"), tr("RTK"), "rtkDock", Qt::RightDockWidgetArea);
    charts_ = new ui::ChartsView(stateModel_, this);
    connect(this, &MainWindow::displayPrefsChanged, charts_, &ui::ChartsView::setDisplayPrefs);
    auto *chartsDock =
            addDock(charts_, tr("Charts"), tr("Charts"), "chartsDock", Qt::BottomDockWidgetArea);
    splitDockWidget(skyDock, signalDock, Qt::Vertical);
    auto *deviation = new ui::DeviationView(stateModel_, this);
    connect(this, &MainWindow::displayPrefsChanged, deviation, &ui::DeviationView::setDisplayPrefs);
    auto *deviationDock = addDock(deviation, tr("Deviation"), tr("Deviation"), "deviationDock",
                                  Qt::LeftDockWidgetArea);
    auto *attitude = new ui::AttitudeView(stateModel_, this);
    connect(this, &MainWindow::displayPrefsChanged, attitude, &ui::AttitudeView::setDisplayPrefs);
    auto *attitudeDock = addDock(attitude, tr("Attitude"), tr("Attitude and time marks"),
                                 "attitudeDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(skyDock, deviationDock);
    skyDock->raise();
    tabifyDockWidget(fixDock, rtkDock);
    // Corrections: a caster's (or a base's) RTCM into the connected receiver, beside RTK.
    corrections_ = new CorrectionsController(settings_, this);
    auto *correctionsView = new ui::CorrectionsView(
            corrections_->monitor(), stateModel_, [this] { return corrections_->forwarderStats(); },
            this);
    connect(this, &MainWindow::displayPrefsChanged, correctionsView,
            &ui::CorrectionsView::setDisplayPrefs);
    correctionsView->setKeychainAvailable(CorrectionsController::keychainAvailable());
    correctionsView->setRequest(corrections_->remembered());
    connect(corrections_, &CorrectionsController::passwordRecalled, correctionsView,
            &ui::CorrectionsView::setPassword);
    connect(corrections_, &CorrectionsController::keychainMessage, correctionsView,
            &ui::CorrectionsView::showError);
    corrections_->recallPassword();
    connect(correctionsView, &ui::CorrectionsView::startRequested, this,
            [this, correctionsView](const ui::CorrectionsRequest &r) {
                QString why;
                if (!corrections_->start(r, &why)) correctionsView->showError(why);
            });
    connect(correctionsView, &ui::CorrectionsView::stopRequested, corrections_,
            &CorrectionsController::stop);
    connect(corrections_, &CorrectionsController::statusChanged, correctionsView,
            &ui::CorrectionsView::setStatus);
    connect(controller_, &ConnectionController::stateChanged, corrections_,
            [this] { corrections_->setReceiver(controller_->connection()); });
    connect(stateModel_, &ui::ReceiverStateModel::updated, corrections_,
            [this] { corrections_->setRoverFix(stateModel_->state().epoch); });
    auto *correctionsDock = addDock(correctionsView, tr("Corrections"), tr("Corrections (RTCM)"),
                                    "correctionsDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(rtkDock, correctionsDock);
    tabifyDockWidget(correctionsDock, infoDock);
    tabifyDockWidget(infoDock, satDock);
    tabifyDockWidget(satDock, attitudeDock);
    // Receiver settings: the engine follows the connection and the dialect it speaks.
    auto *settingsEngine = new config::SettingsEngine(this);
    tabifyDockWidget(attitudeDock,
                     addDock(new ui::SettingsView(settingsEngine, this), tr("Settings"),
                             tr("Receiver settings"), "settingsDock", Qt::RightDockWidgetArea));
    connect(session_, &ui::ReceiverSession::dialectChanged, settingsEngine,
            [this, settingsEngine](const Dialect *d) {
                settingsEngine->attach(controller_->connection(), d);
            });
    connect(controller_, &ConnectionController::stateChanged, settingsEngine,
            [this, settingsEngine] {
                settingsEngine->attach(controller_->connection(), session_->dialect());
            });
    fixDock->raise();
    createLogViewer();
    tabifyDockWidget(consoleDock, statsDock);
    tabifyDockWidget(statsDock, chartsDock);
    consoleDock->raise();
    connect(consoleView_, &ui::ConsoleView::sendRequested, this, [this](const QByteArray &s) {
        QString why;
        if (!controller_->send(s, &why)) {
            consoleView_->showNotSent(why);
            statusBar()->showMessage(tr("Not sent: %1").arg(why), 8000);
        }
    });
    connect(session_, &ui::ReceiverSession::dialectChanged, this, [this](const Dialect *d) {
        QStringList names;
        if (d)
            for (auto n : d->commandNames) names << QString::fromLatin1(n.data(), int(n.size()));
        consoleView_->setCommandNames(names);
        consoleView_->setExample(
                d ? QString::fromLatin1(d->consoleExample.data(), int(d->consoleExample.size()))
                  : QString());
        // The sky plot draws the elevation mask: the schema's default until the receiver's own
        // value is read (below).
        if (const SettingDef *m = elevationMaskSetting(d)) {
            bool ok = false;
            const double v =
                    QString::fromLatin1(m->defaultValue.data(), int(m->defaultValue.size()))
                            .toDouble(&ok);
            sky_->setElevationMask(ok ? v : -1);
        } else {
            sky_->setElevationMask(-1);
        }
    });
    connect(settingsEngine, &config::SettingsEngine::valuesChanged, this, [this, settingsEngine] {
        const SettingDef *m = elevationMaskSetting(settingsEngine->dialect());
        if (!m) return;
        if (const auto v = settingsEngine->receiverValue(m->key)) {
            bool ok = false;
            const double deg = QString::fromStdString(*v).toDouble(&ok);
            if (ok) sky_->setElevationMask(deg);
        }
    });
}

const SettingDef *MainWindow::elevationMaskSetting(const Dialect *d) {
    // Whatever the vendor calls it: the schema row with the elevation-mask role.
    return d ? findSettingByRole(d->settings, SettingRole::ElevationMask) : nullptr;
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
    receiver->addAction(tr("&Connect"), this, [this] { controller_->connectTo(bar_->selection()); })
            ->setShortcut(QKeySequence(tr("Ctrl+K")));
    receiver->addAction(tr("&Disconnect"), controller_, &ConnectionController::disconnectFromSource)
            ->setShortcut(QKeySequence(tr("Ctrl+Shift+K")));

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->setObjectName("viewMenu");
    for (QDockWidget *d : findChildren<QDockWidget *>())
        viewMenu_->addAction(d->toggleViewAction());
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
    stateLabel_->setText(log ? logViewer_->statusText() : controller_->stateText());
    // The whole text too, for a message longer than the status bar shows.
    stateLabel_->setToolTip(log ? logViewer_->path()
                            : controller_->detectionDetail().isEmpty()
                                    ? controller_->stateText()
                                    : controller_->detectionDetail());
    const Dialect *d = log ? logViewer_->dialectAtCursor() : session_->dialect();
    const ReceiverIdentity &id = stateModel_->state().identity;
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
    const bool rec = controller_->recording();
    recordLabel_->setText(rec ? tr("● REC") : QString());
    recordLabel_->setStyleSheet(
            rec ? QStringLiteral("color: %1; font-weight: bold;").arg(style::errorColor().name())
                : QString());
    // The badge is the live fix: none once the receiver is disconnected (the docks keep the last).
    const auto link = controller_->state();
    const bool live = link != ConnectionController::State::Disconnected &&
                      link != ConnectionController::State::Failed;
    const bool any = (live || log) && stateModel_->epochCount() > 0;
    const FixType fix = any ? stateModel_->state().epoch.fix : FixType::None;
    fixLabel_->setText(any ? style::fixTypeLabel(fix) : tr("No fix"));
    fixLabel_->setStyleSheet(style::badgeCss(style::fixTypeColor(fix), 4, "1px 6px"));
}

void MainWindow::toggleRecording(bool on) {
    if (!on) {
        controller_->stopRecording();
        updateStatus();
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
            this, tr("Record to"), QStringLiteral("receiver.nmea"), tr("NMEA logs (*.nmea)"));
    if (path.isEmpty() || !controller_->startRecording(path)) {
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
    const SourceSpec s = controller_->source();
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
    controller_->setBaudCandidates(prefs_.detectionBauds);
    emit displayPrefsChanged(prefs_.display);
}

void MainWindow::setPreferences(const Preferences &p) {
    const Preferences before = prefs_;
    prefs_ = p;
    if (settings_) p.save(*settings_);
    if (p.theme != before.theme) applyTheme(p.theme);
    for (QAction *a : themeActions_) a->setChecked(a->data().toString() == p.theme);
    controller_->setBaudCandidates(p.detectionBauds);
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
    const QStringList simulated = simulatedDialects(registry_);
    if (!s.valid() && !simulated.isEmpty())
        s = SourceSpec{SourceSpec::Kind::Simulator, simulated.front()};
    bar_->select(s);
    controller_->connectTo(s);
}

void MainWindow::closeEvent(QCloseEvent *e) {
    saveLayout();
    controller_->disconnectFromSource(); // flushes a recording
    QMainWindow::closeEvent(e);
}

} // namespace gnss::app
