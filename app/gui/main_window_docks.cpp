// MainWindow's docks: each made from its row of the dock table (dock_table.h) for the session it
// shows, laid out by the table, and the wiring each view needs in its own maker.
#include "gui/corrections_controller.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "logview/log_events_view.h"
#include "logview/log_summary_view.h"
#include "logview/whole_log_panels.h"
#include "models/receiver_session.h"
#include "session/receiver_link.h"
#include "settings/settings_view.h"
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
#include <QDockWidget>
#include <QFileDialog>
#include <QHeaderView>
#include <QStatusBar>
#include <QTableView>

namespace gnss::app {

void MainWindow::createDocks() {
    // Each dock joins its group's tab bar (or is split below its neighbour) as it is made: docks
    // stacked in an area before being tabbed would leave the layout sized for the stack.
    QHash<QString, QDockWidget *> groupEnd;
    for (const DockRow &row : dockRows()) {
        // Tabs show the short title (whole even at 1280 px); the View menu the full one.
        auto *d = new QDockWidget(dockTitle(row), this);
        d->setObjectName(dockObjectName(row));
        d->setWidget((this->*row.make)(*session_));
        d->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                       QDockWidget::DockWidgetFloatable);
        d->toggleViewAction()->setText(dockFullTitle(row));
        d->toggleViewAction()->setToolTip(dockFullTitle(row));
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
    for (const DockRow &row : dockRows())
        if (row.front && !row.log) dock(dockObjectName(row))->raise();
}

QWidget *MainWindow::makeSkyPlot(ui::ReceiverSession &s) {
    sky_ = new ui::SkyPlotView(s.satellites(), this);
    followElevationMask(s, sky_);
    return sky_;
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
    consoleView_ = view;
    connect(this, &MainWindow::displayPrefsChanged, s.console(),
            [this, &s](const ui::DisplayPrefs &p) {
                s.console()->setTimeZone(p.time);
                logViewer_->lines()->setTimeZone(p.time);
            });
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
    connect(this, &MainWindow::displayPrefsChanged, s.messages(),
            [&s](const ui::DisplayPrefs &p) { s.messages()->setTimeZone(p.time); });
    return new ui::MessageStatsView(s.messages(), this);
}

QWidget *MainWindow::makeReceiverInfo(ui::ReceiverSession &s) {
    return new ui::ReceiverInfoView(s.state(), this);
}

QWidget *MainWindow::makeRtk(ui::ReceiverSession &s) {
    rtk_ = new ui::RtkView(s.state(), this);
    followDisplayPrefs(rtk_);
    return rtk_;
}

QWidget *MainWindow::makeCharts(ui::ReceiverSession &s) {
    charts_ = new ui::ChartsView(s.state(), this);
    followDisplayPrefs(charts_);
    return charts_;
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

QWidget *MainWindow::makeCorrections(ui::ReceiverSession &s) {
    // Corrections: a caster's (or a base's) RTCM into the session's receiver, beside RTK.
    session::ReceiverLink *link = s.link();
    corrections_->setTarget(link);
    auto *view = new ui::CorrectionsView(
            corrections_->monitor(), s.state(), [link] { return link->forwarderStats(); }, this);
    followDisplayPrefs(view);
    view->setKeychainAvailable(CorrectionsController::keychainAvailable());
    view->setRequest(corrections_->remembered());
    connect(corrections_, &CorrectionsController::passwordRecalled, view,
            &ui::CorrectionsView::setPassword);
    connect(corrections_, &CorrectionsController::keychainMessage, view,
            &ui::CorrectionsView::showError);
    corrections_->recallPassword();
    connect(view, &ui::CorrectionsView::startRequested, this,
            [this, view](const ui::CorrectionsRequest &r) {
                QString why;
                if (!corrections_->start(r, &why)) view->showError(why);
            });
    connect(view, &ui::CorrectionsView::stopRequested, corrections_, &CorrectionsController::stop);
    connect(corrections_, &CorrectionsController::statusChanged, view,
            &ui::CorrectionsView::setStatus);
    connect(s.state(), &ui::ReceiverStateModel::updated, corrections_,
            [this, &s] { corrections_->setRoverFix(s.state()->state().epoch); });
    return view;
}

QWidget *MainWindow::makeSettings(ui::ReceiverSession &s) {
    // The session's engine follows its connection and the dialect it speaks.
    return new ui::SettingsView(s.link()->settings(), this);
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
