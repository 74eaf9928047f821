// MainWindow's docks: each made from its row of the dock table (dock_table.h) for the session it
// shows, laid out by the table, and the wiring each view needs in its own maker.
#include "base/base_station_view.h"
#include "base/base_status.h"
#include "config/settings_engine.h"
#include "gui/corrections_controller.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "gui/qualification_controller.h"
#include "gui/serve_controller.h"
#include "logview/log_events_view.h"
#include "logview/log_summary_view.h"
#include "logview/whole_log_panels.h"
#include "models/compare_model.h"
#include "models/receiver_session.h"
#include "qualify/accuracy_panel.h"
#include "session/receiver_link.h"
#include "settings/settings_view.h"
#include "views/attitude_view.h"
#include "views/charts_view.h"
#include "views/cn0_map_view.h"
#include "views/compare_view.h"
#include "views/console_view.h"
#include "views/corrections_view.h"
#include "views/deviation_view.h"
#include "views/fix_view.h"
#include "views/message_stats_view.h"
#include "views/receiver_info_view.h"
#include "views/rtk_view.h"
#include "views/signal_history_view.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"
#include "widgets/fitted_columns.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QHeaderView>
#include <QSplitter>
#include <QStatusBar>
#include <QTableView>
#include <QTimer>

namespace gnss::app {

void MainWindow::createDocks() {
    // Each dock joins its group's tab bar (or is split below its neighbour) as it is made: docks
    // stacked in an area before being tabbed would leave the layout sized for the stack.
    QHash<QString, QDockWidget *> groupEnd;
    for (const DockRow &row : dockRows()) {
        QDockWidget *d = makeDock(row, dockObjectName(row), row.log ? *logSession_ : *current_);
        addDockWidget(row.area, d);
        if (row.log) { // the log's docks join their groups when the first log opens
            d->hide();
            continue;
        }
        if (row.below) {
            splitDockWidget(dock(QLatin1String(row.below) + QLatin1String("Dock")), d,
                            Qt::Vertical);
        } else if (row.tabGroup) {
            const QString group = QLatin1String(row.tabGroup);
            if (QDockWidget *before = groupEnd.value(group)) tabifyDockWidget(before, d);
            groupEnd.insert(group, d);
        }
    }
    for (const DockRow &row : dockRows()) {
        if (row.front && !row.log) dock(dockObjectName(row))->raise();
        if (!row.putAway) continue;
        QDockWidget *d = dock(dockObjectName(row));
        d->hide();
        // Brought out (a campaign's form, table and plots), it gets room: the bottom row of a
        // laptop's layout is a few lines tall.
        connect(d, &QDockWidget::visibilityChanged, this, [this, d](bool visible) {
            if (visible && !d->isFloating() && d->height() < height() * 0.35)
                QTimer::singleShot(0, this, [this, d] {
                    resizeDocks({d}, {int(height() * 0.42)}, Qt::Vertical);
                });
        });
    }
}

QDockWidget *MainWindow::makeDock(const DockRow &row, const QString &objectName,
                                  ui::ReceiverSession &s) {
    // Tabs show the short title (whole even at 1280 px); the View menu the full one.
    auto *d = new QDockWidget(dockTitle(row), this);
    d->setObjectName(objectName);
    docks_.insert(d, DockBinding{&row, &s, nullptr, false});
    d->setWidget((this->*row.make)(s));
    d->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                   QDockWidget::DockWidgetFloatable);
    d->toggleViewAction()->setText(dockFullTitle(row));
    d->toggleViewAction()->setToolTip(dockFullTitle(row));
    if (!row.log && !row.window) {
        // Its menu (on the title, or on a view with none of its own): pin, another like it.
        d->setContextMenuPolicy(Qt::CustomContextMenu);
        connect(d, &QWidget::customContextMenuRequested, this,
                [this, d](const QPoint &at) { dockMenu(d, d->mapToGlobal(at)); });
    }
    return d;
}

QWidget *MainWindow::makeSkyPlot(ui::ReceiverSession &s) {
    auto *sky = new ui::SkyPlotView(s.satellites(), this);
    sky->setShowTracks(skyTracks_);
    followElevationMask(s, sky);
    return sky;
}

QWidget *MainWindow::makeFix(ui::ReceiverSession &s) {
    auto *view = new ui::FixView(s.state(), this);
    followDisplayPrefs(view);
    connect(view, &ui::FixView::coordinateFormatChosen, this, [this](ui::CoordinateFormat f) {
        Preferences p = prefs_;
        p.display.coordinates = f;
        setPreferences(p);
    });
    return view;
}

QWidget *MainWindow::makeSignalLevels(ui::ReceiverSession &s) {
    return new ui::SignalLevelsView(s.satellites(), this);
}

QWidget *MainWindow::makeSatellites(ui::ReceiverSession &s) {
    auto *table = new QTableView(this);
    table->setObjectName("satelliteTable");
    table->setModel(s.satellites());
    table->verticalHeader()->hide();
    // Rewritten whole at every epoch: measured when satellites come or go and once a second.
    new ui::FittedColumns(table, table->horizontalHeader());
    return table;
}

QWidget *MainWindow::makeConsole(ui::ReceiverSession &s) {
    auto *view = new ui::ConsoleView(s.console(), this);
    view->setHistory(consoleHistory_);
    connect(
            view, &ui::ConsoleView::sendRequested, this,
            [this, view] { consoleHistory_ = view->history(); }, Qt::QueuedConnection);
    if (&s == logSession_) {
        // The log's own lines, filtered by the model (a whole log, on a worker).
        wireLogConsole(view);
        return view;
    }
    session::ReceiverLink *link = s.link();
    connect(view, &ui::ConsoleView::sendRequested, this,
            [this, view, link](const QByteArray &line) {
                QString why;
                if (!link->send(line, &why)) {
                    view->showNotSent(why);
                    statusBar()->showMessage(tr("Not sent: %1").arg(why), 8000);
                }
            });
    // The send box is off, with why, while the link takes no commands (gpsd owns the port).
    connect(link, &session::ReceiverLink::stateChanged, view,
            [view, link] { view->setSendRefusal(link->sendRefusal()); });
    // The dialect's command names (completion) and example.
    connect(&s, &ui::ReceiverSession::dialectChanged, view, [view](const Dialect *d) {
        QStringList names;
        if (d)
            for (auto n : d->commandNames) names << QString::fromLatin1(n.data(), int(n.size()));
        view->setCommandNames(names);
        view->setExample(
                d ? QString::fromLatin1(d->consoleExample.data(), int(d->consoleExample.size()))
                  : QString());
    });
    return view;
}

QWidget *MainWindow::makeStatistics(ui::ReceiverSession &s) {
    return new ui::MessageStatsView(s.messages(), this);
}

QWidget *MainWindow::makeReceiverInfo(ui::ReceiverSession &s) {
    return new ui::ReceiverInfoView(s.state(), this);
}

QWidget *MainWindow::makeRtk(ui::ReceiverSession &s) {
    auto *rtk = new ui::RtkView(s.state(), this);
    followDisplayPrefs(rtk);
    return rtk;
}

QWidget *MainWindow::makeCharts(ui::ReceiverSession &s) {
    auto *charts = new ui::ChartsView(s.state(), this);
    followDisplayPrefs(charts);
    return charts;
}

QWidget *MainWindow::makeDeviation(ui::ReceiverSession &s) {
    auto *view = new ui::DeviationView(s.state(), this);
    followDisplayPrefs(view);
    return view;
}

QWidget *MainWindow::makeAttitude(ui::ReceiverSession &s) {
    auto *view = new ui::AttitudeView(s.state(), this);
    followDisplayPrefs(view);
    return view;
}

CorrectionsController *MainWindow::corrections(ui::ReceiverSession *s) {
    if (!s) s = current_;
    if (!s) return nullptr;
    QPointer<CorrectionsController> &c = corrections_[s];
    if (!c) {
        // The receiver's own: it goes with it, and its fix goes up to the caster as the GGA
        // whichever receiver the docks show.
        c = new CorrectionsController(settings_, s);
        c->setTarget(s->link());
        CorrectionsController *controller = c;
        connect(s->state(), &ui::ReceiverStateModel::updated, controller,
                [controller, s] { controller->setRoverFix(s->state()->state().epoch); });
    }
    return c;
}

QWidget *MainWindow::makeCorrections(ui::ReceiverSession &s) {
    // Corrections: a caster's (or a base's) RTCM into the session's receiver, beside RTK.
    session::ReceiverLink *link = s.link();
    CorrectionsController *c = corrections(&s);
    auto *view = new ui::CorrectionsView(
            c->monitor(), s.state(), [link] { return link->forwarderStats(); }, this);
    followDisplayPrefs(view);
    view->setKeychainAvailable(CorrectionsController::keychainAvailable());
    view->setRequest(c->remembered());
    connect(c, &CorrectionsController::passwordRecalled, view, &ui::CorrectionsView::setPassword);
    connect(c, &CorrectionsController::keychainMessage, view, &ui::CorrectionsView::showError);
    c->recallPassword();
    connect(view, &ui::CorrectionsView::startRequested, c,
            [c, view](const ui::CorrectionsRequest &r) {
                QString why;
                if (!c->start(r, &why)) view->showError(why);
            });
    connect(view, &ui::CorrectionsView::stopRequested, c, &CorrectionsController::stop);
    connect(c, &CorrectionsController::statusChanged, view,
            [c, view](const QString &text, bool active) {
                view->setOwnOutput(c->showingOwnOutput());
                view->setStatus(text, active);
            });
    view->setOwnOutput(c->showingOwnOutput());
    // A base of this window set to send the same station: its position against the 1005/1006.
    view->setSetBaseLookup([this](unsigned station) -> std::optional<ui::CorrectionsView::SetBase> {
        for (ui::ReceiverSession *r : std::as_const(sessions_)) {
            const config::SettingsEngine *engine = r->link()->settings();
            const auto roles = engine && engine->dialect() ? base::baseRoles(*engine->dialect())
                                                           : std::nullopt;
            if (!roles) continue;
            const base::BaseStatus b = base::baseStatus(
                    *roles, [engine](std::string_view k) { return engine->receiverValue(k); },
                    std::nullopt);
            if (b.isBase() && b.position && b.station == std::to_string(station))
                return ui::CorrectionsView::SetBase{r->name(), *b.position};
        }
        return std::nullopt;
    });
    view->setStatus(c->statusText(), c->active()); // a stream of its own may be running
    return view;
}

QWidget *MainWindow::makeSettings(ui::ReceiverSession &s) {
    // The session's engine follows its connection and the dialect it speaks.
    return new ui::SettingsView(s.link()->settings(), this);
}

QWidget *MainWindow::makeSignalHistory(ui::ReceiverSession &s) {
    // C/N0 over time beside the polar C/N0 map, both from the session's signal history.
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName("signalHistorySplit");
    auto *view = new ui::SignalHistoryView(s.signalHistory(), split);
    view->setLive(&s != logSession_);
    split->addWidget(view);
    split->addWidget(new ui::Cn0MapView(s.signalHistory(), split));
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    return split;
}

QWidget *MainWindow::makeCompare(ui::ReceiverSession &) {
    // Every receiver of the window, the first the reference; made again when one is added or
    // closed.
    if (!compare_) {
        compare_ = new ui::CompareModel(this);
        connect(this, &MainWindow::receiversChanged, this, &MainWindow::updateCompareReceivers);
        updateCompareReceivers();
    }
    auto *view = new ui::CompareView(compare_, this);
    connect(view, &ui::CompareView::exportRequested, this, [this](bool json) {
        const QString path = QFileDialog::getSaveFileName(
                this, tr("Export the comparison"),
                json ? QStringLiteral("comparison.json") : QStringLiteral("comparison.csv"),
                json ? tr("JSON (*.json)") : tr("CSV (*.csv)"));
        if (path.isEmpty()) return;
        QFile f(path);
        if (f.open(QIODevice::WriteOnly) &&
            f.write(json ? compare_->json() : compare_->csv()) >= 0 && f.flush())
            statusBar()->showMessage(tr("Saved %1").arg(path), 8000);
        else
            statusBar()->showMessage(tr("Not saved: %1").arg(f.errorString()), 10000);
    });
    return view;
}

QualificationController *MainWindow::qualification() {
    if (!qualification_) {
        qualification_ = new QualificationController(
                {[this] { return sessions_; }, [this] { return current_; }}, this);
        qualification_->setDisplayPrefs(prefs_.display);
        connect(this, &MainWindow::displayPrefsChanged, qualification_,
                &QualificationController::setDisplayPrefs);
        connect(qualification_, &QualificationController::message, this,
                [this](const QString &m) { statusBar()->showMessage(m, 10000); });
        for (ui::ReceiverSession *s : sessions_) qualification_->follow(s);
    }
    return qualification_;
}

void MainWindow::useSites(ui::AccuracyPanel *panel) {
    panel->setSiteStore(&siteStore_);
    connect(panel, &ui::AccuracyPanel::message, this,
            [this](const QString &m) { statusBar()->showMessage(m, 10000); });
}

QWidget *MainWindow::makeQualification(ui::ReceiverSession &) {
    auto *view = new ui::QualificationView(this);
    qualification()->attach(view);
    useSites(view->accuracy());
    connect(this, &MainWindow::receiversChanged, view,
            [this, view] { view->setReceiverCount(int(sessions_.size())); });
    connect(view, &ui::QualificationView::reportRequested, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save the qualification report"),
                                                          QStringLiteral("qualification.pdf"),
                                                          tr("PDF (*.pdf);;HTML (*.html)"));
        if (path.isEmpty()) return;
        QString error;
        const QStringList files = qualification_->writeReport(path, &error);
        statusBar()->showMessage(
                files.isEmpty() ? error : tr("Report written: %1").arg(files.join(", ")), 15000);
    });
    return view;
}

ServeController *MainWindow::serving() {
    if (!serve_) {
        serve_ = new ServeController({[this] { return sessions_; },
                                      [this](ui::ReceiverSession *s) { return corrections(s); }},
                                     this);
        connect(this, &MainWindow::receiversChanged, serve_, &ServeController::refresh);
        connect(serve_, &ServeController::message, this,
                [this](const QString &m) { statusBar()->showMessage(m, 10000); });
    }
    return serve_;
}

QWidget *MainWindow::makeServe(ui::ReceiverSession &) {
    // Every receiver of the window: its RTCM or the corrections it is fed, as mountpoints.
    auto *view = new ui::ServeView(this);
    serving()->attach(view);
    return view;
}

QWidget *MainWindow::makeBaseStation(ui::ReceiverSession &s) {
    // The receiver as an RTK base: its settings engine and its epochs, the window's sites.
    auto *view = new ui::BaseStationView(s.link()->settings(), s.state(), this);
    view->setSiteStore(&siteStore_);
    followDisplayPrefs(view);
    connect(view, &ui::BaseStationView::message, this,
            [this](const QString &m) { statusBar()->showMessage(m, 10000); });
    return view;
}

void MainWindow::updateCompareReceivers() {
    if (!compare_) return;
    QList<ui::CompareModel::Receiver> list;
    for (ui::ReceiverSession *s : std::as_const(sessions_))
        list << ui::CompareModel::Receiver{s->state(), s->name(), s->colour()};
    compare_->setReceivers(list);
}

void MainWindow::followElevationMask(ui::ReceiverSession &s, ui::SkyPlotView *sky) {
    // The sky plot draws the elevation mask: the schema's default until the receiver's own value
    // is read (below).
    connect(&s, &ui::ReceiverSession::dialectChanged, sky, [sky](const Dialect *d) {
        if (const SettingDef *m = elevationMaskSetting(d)) {
            bool ok = false;
            const double v =
                    QString::fromLatin1(m->defaultValue.data(), int(m->defaultValue.size()))
                            .toDouble(&ok);
            sky->setElevationMask(ok ? v : -1);
        } else {
            sky->setElevationMask(-1);
        }
    });
    config::SettingsEngine *engine = s.link()->settings();
    connect(engine, &config::SettingsEngine::valuesChanged, sky, [sky, engine] {
        const SettingDef *m = elevationMaskSetting(engine->dialect());
        if (!m) return;
        if (const auto v = engine->receiverValue(m->key)) {
            bool ok = false;
            const double deg = QString::fromStdString(*v).toDouble(&ok);
            if (ok) sky->setElevationMask(deg);
        }
    });
}

const SettingDef *MainWindow::elevationMaskSetting(const Dialect *d) {
    // Whatever the vendor calls it: the schema row with the elevation-mask role.
    return d ? findSettingByRole(d->settings, SettingRole::ElevationMask) : nullptr;
}

QWidget *MainWindow::makeLogEvents(ui::ReceiverSession &) {
    auto *events = new ui::LogEventsView(logViewer_->cursor(), registry_, this);
    connect(events, &ui::LogEventsView::exportRequested, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
                this, tr("Save events"), QStringLiteral("events.csv"), tr("CSV (*.csv)"));
        QString why;
        if (!path.isEmpty() && !logViewer_->exportTo(LogViewer::Export::EventsCsv, path, &why))
            statusBar()->showMessage(tr("Not exported: %1").arg(why), 8000);
    });
    return events;
}

QWidget *MainWindow::makeLogSummary(ui::ReceiverSession &) {
    auto *summary = new ui::LogSummaryView(logViewer_->cursor(), this);
    followDisplayPrefs(summary);
    useSites(summary->accuracy());
    connect(summary, &ui::LogSummaryView::exportRequested, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save statistics"),
                                                          QStringLiteral("statistics.json"),
                                                          tr("JSON (*.json)"));
        QString why;
        if (!path.isEmpty() && !logViewer_->exportTo(LogViewer::Export::StatsJson, path, &why))
            statusBar()->showMessage(tr("Not exported: %1").arg(why), 8000);
    });
    return summary;
}

QWidget *MainWindow::makeLogCharts(ui::ReceiverSession &) {
    auto *charts = new ui::LogChartsPanel(logViewer_->cursor(), this);
    followDisplayPrefs(charts->plot());
    return charts;
}

QWidget *MainWindow::makeLogTrack(ui::ReceiverSession &) {
    auto *track = new ui::LogTrackPanel(logViewer_->cursor(), this);
    followDisplayPrefs(track->track());
    return track;
}

} // namespace gnss::app
