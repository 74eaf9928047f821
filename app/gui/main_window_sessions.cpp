// MainWindow's receivers: adding, selecting, renaming and closing them, the docks that follow the
// selection or are pinned to one receiver, and the set of receivers kept for the next start.
#include "gui/connection_bar.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "gui/qualification_controller.h"
#include "gui/receivers_strip.h"
#include "link/connection.h"
#include "link/recording_name.h"
#include "link/serial_transport.h"
#include "models/receiver_session.h"
#include "session/receiver_link.h"
#include "settings/settings_view.h"
#include "style/gnss_style.h"
#include "views/charts_view.h"
#include "views/console_view.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QInputDialog>
#include <QMenu>
#include <QPixmap>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>

namespace gnss::app {

namespace {
// Okabe and Ito's colours: told apart by people with any colour blindness, on light and dark.
constexpr const char *kColours[] = {"#0072B2", "#E69F00", "#009E73", "#CC79A7",
                                    "#56B4E9", "#D55E00", "#F0E442", "#999999"};

QIcon swatch(const QColor &c) {
    QPixmap p(12, 12);
    p.fill(c);
    return QIcon(p);
}

} // namespace

ui::ReceiverSession *MainWindow::newSession() {
    auto *s = new ui::ReceiverSession(registry_, transports_, this);
    s->setObjectName(QStringLiteral("session%1").arg(++sessionsMade_));
    // The first colour no other receiver has.
    for (const char *c : kColours) {
        const QColor colour = QColor::fromString(QLatin1String(c));
        bool used = false;
        for (const ui::ReceiverSession *o : sessions_) used = used || o->colour() == colour;
        if (!used) {
            s->setColour(colour);
            break;
        }
    }
    if (!s->colour().isValid())
        s->setColour(QColor::fromString(QLatin1String(kColours[sessions_.size() % 8])));
    s->link()->setBaudCandidates(prefs_.detectionBauds);
    s->console()->setTimeZone(prefs_.display.time);
    s->messages()->setTimeZone(prefs_.display.time);
    connect(this, &MainWindow::displayPrefsChanged, s, [s](const ui::DisplayPrefs &p) {
        s->console()->setTimeZone(p.time);
        s->messages()->setTimeZone(p.time);
    });
    sessions_ << s;
    if (qualification_) qualification_->follow(s);
    return s;
}

ui::ReceiverSession *MainWindow::addReceiver(const SourceSpec &spec) {
    ui::ReceiverSession *s = newSession();
    wireSession(s);
    rebuildReceiverActions();
    selectReceiver(s);
    if (spec.valid()) connectReceiver(s, spec);
    emit receiversChanged();
    return s;
}

bool MainWindow::portTakenByAnother(const SourceSpec &spec, const ui::ReceiverSession *asking) {
    if (spec.kind != SourceSpec::Kind::Serial) return false; // TCP, gpsd, files and sims share
    for (qsizetype i = 0; i < sessions_.size(); ++i) {
        ui::ReceiverSession *other = sessions_[i];
        const SourceSpec has = other->link()->source();
        const auto state = other->link()->state();
        if (other == asking || has.kind != SourceSpec::Kind::Serial ||
            state == session::ReceiverLink::State::Disconnected ||
            state == session::ReceiverLink::State::Failed ||
            !link::sameSerialDevice(has.name, spec.name))
            continue;
        selectReceiver(other);
        statusBar()->showMessage(tr("%1 is receiver %2 already (%3): choose another port.")
                                         .arg(spec.name, QString::number(i + 1), other->name()),
                                 10000);
        return true;
    }
    return false;
}

void MainWindow::connectReceiver(ui::ReceiverSession *s, const SourceSpec &spec) {
    // A live source asked for closes the log (the docks that follow show one thing at a time).
    if (logViewer_ && logViewer_->isOpen()) closeLog();
    s->link()->connectTo(spec);
    updateStatus();
}

void MainWindow::closeReceiver(ui::ReceiverSession *s) {
    if (!s || !sessions_.contains(s)) return;
    if (sessions_.size() == 1) {
        s->link()->disconnectFromSource();
        return;
    }
    // Its own docks go with it; the main ones pinned to it follow the selection again.
    for (auto it = docks_.begin(); it != docks_.end();) {
        if (it->pinned == s && it->duplicate) {
            QDockWidget *d = it.key();
            it = docks_.erase(it);
            removeDockWidget(d);
            d->deleteLater();
            continue;
        }
        if (it->pinned == s) it->pinned = nullptr;
        ++it;
    }
    sessions_.removeOne(s);
    corrections_.remove(s);            // its stream goes with it
    s->link()->disconnectFromSource(); // flushes its recording
    if (current_ == s) current_ = sessions_.front();
    rebindFollowingDocks();
    s->deleteLater();
    rebuildReceiverActions();
    selectReceiver(current_);
    emit receiversChanged();
}

void MainWindow::selectReceiver(ui::ReceiverSession *s) {
    if (!s || !sessions_.contains(s)) return;
    const bool changed = s != current_;
    current_ = s;
    // The docks show one thing at a time: a receiver chosen closes the log.
    if (changed && logViewer_ && logViewer_->isOpen()) closeLog();
    rebindFollowingDocks();
    for (int i = 0; i < receiverActions_.size(); ++i)
        receiverActions_[i]->setChecked(sessions_.value(i) == current_);
    if (current_->link()->source().valid()) bar_->select(current_->link()->source());
    refreshBar();
    updateStatus();
}

void MainWindow::refreshBar() {
    const session::ReceiverLink *lk = current_->link();
    const auto st = lk->state();
    bar_->setConnected(st != session::ReceiverLink::State::Disconnected &&
                       st != session::ReceiverLink::State::Failed);
    if (st == session::ReceiverLink::State::Detecting) return; // "trying …" comes by itself
    bar_->setBaudNote(lk->detectedBaud() > 0 ? tr("→ %1").arg(lk->detectedBaud()) : QString(),
                      lk->detectionDetail());
}

ui::ReceiverSession *MainWindow::dockSession(QDockWidget *d) const {
    return docks_.value(d).shown;
}

ui::ReceiverSession *MainWindow::pinnedSession(QDockWidget *d) const {
    return docks_.value(d).pinned;
}

void MainWindow::bindDock(QDockWidget *d, ui::ReceiverSession *s) {
    auto it = docks_.find(d);
    if (it == docks_.end() || !s || it->shown == s) return;
    QWidget *old = d->widget();
    QWidget *view = (this->*it->row->make)(*s);
    // What the user chose in the view stays as it was.
    auto *oldCharts = qobject_cast<ui::ChartsView *>(old);
    if (auto *charts = qobject_cast<ui::ChartsView *>(view); charts && oldCharts) {
        charts->setCheckedSeries(oldCharts->checkedSeries());
        charts->setWindowMinutes(oldCharts->windowMinutes());
    }
    it->shown = s;
    d->setWidget(view);
    delete old; // at once: nothing may find two views of one dock
}

bool MainWindow::holdsWork(const QWidget *view) {
    if (const auto *form = qobject_cast<const ui::SettingsView *>(view))
        return !form->edits().empty();
    if (const auto *console = qobject_cast<const ui::ConsoleView *>(view))
        return !console->typedCommand().trimmed().isEmpty();
    return false;
}

void MainWindow::rebindFollowingDocks() {
    // New views have sizes of their own: the docks keep the ones the user gave them.
    const QByteArray layout = saveState();
    bool changed = false;
    const auto keys = docks_.keys();
    for (QDockWidget *d : keys) {
        const DockBinding b = docks_.value(d);
        if (b.row->log || b.row->window) continue;
        ui::ReceiverSession *s = b.pinned ? b.pinned.data() : session();
        // Work begun for a receiver keeps it (the dock is pinned to it): a settings form with
        // changes not yet applied, a command typed and not sent. They were meant for that one,
        // and would be lost, or sent to another.
        if (!b.pinned && b.shown && b.shown != s && b.shown != logSession_ &&
            holdsWork(d->widget())) {
            docks_[d].pinned = b.shown;
            statusBar()->showMessage(tr("%1 keeps what was begun for %2: pinned to it")
                                             .arg(dockTitle(*b.row), b.shown->name()),
                                     10000);
            continue;
        }
        changed = changed || b.shown != s;
        bindDock(d, s);
    }
    if (changed) restoreState(layout);
    updateDockTitles();
}

void MainWindow::pinDock(QDockWidget *d, ui::ReceiverSession *s) {
    auto it = docks_.find(d);
    if (it == docks_.end() || it->row->log || it->row->window) return;
    if (s && !sessions_.contains(s)) return;
    it->pinned = s;
    bindDock(d, s ? s : session());
    updateDockTitles();
}

QDockWidget *MainWindow::duplicateDock(const QString &name, ui::ReceiverSession *s,
                                       const QString &objectName) {
    const DockRow *row = findDockRow(name);
    if (!row || row->log || row->window || !s || !sessions_.contains(s)) return nullptr;
    QString object = objectName;
    for (int n = 2; object.isEmpty() || dock(object); ++n)
        object = QStringLiteral("%1-%2").arg(dockObjectName(*row)).arg(n);
    QDockWidget *d = makeDock(*row, object, *s);
    docks_[d].pinned = s;
    docks_[d].duplicate = true;
    // Closed, it is gone (the main dock of its kind stays in the View menu).
    d->setAttribute(Qt::WA_DeleteOnClose);
    connect(d, &QObject::destroyed, this, [this, d] { docks_.remove(d); });
    addDockWidget(row->area, d);
    // Side by side with the first of its kind: two Fix docks, base and rover.
    if (QDockWidget *first = dock(dockObjectName(*row)); first && first->isVisible())
        splitDockWidget(first, d, Qt::Horizontal);
    updateDockTitles();
    return d;
}

void MainWindow::dockMenu(QDockWidget *d, const QPoint &globalPos) {
    const DockBinding b = docks_.value(d);
    if (!b.row) return;
    QMenu menu(this);
    QAction *follow = menu.addAction(tr("Follow the selected receiver"), this,
                                     [this, d] { pinDock(d, nullptr); });
    follow->setCheckable(true);
    follow->setChecked(!b.pinned);
    for (ui::ReceiverSession *s : sessions_) {
        QAction *pin = menu.addAction(swatch(s->colour()), tr("Pin to %1").arg(s->name()), this,
                                      [this, d, s] { pinDock(d, s); });
        pin->setCheckable(true);
        pin->setChecked(b.pinned == s);
    }
    menu.addSeparator();
    menu.addAction(tr("Another dock like this one"), this, [this, b] {
        ui::ReceiverSession *s = b.pinned ? b.pinned.data() : current_;
        if (QDockWidget *copy = duplicateDock(QLatin1String(b.row->name), s)) {
            copy->show();
            copy->raise();
        }
    });
    if (b.duplicate) menu.addAction(tr("Close this dock"), d, &QWidget::close);
    menu.exec(globalPos);
}

QString MainWindow::receiverLabel(const ui::ReceiverSession *s) const {
    const QString shortName = s->shortName();
    for (const ui::ReceiverSession *o : sessions_)
        if (o != s && o->shortName() == shortName) return s->name();
    return shortName;
}

void MainWindow::updateDockTitles() {
    const bool several = sessions_.size() > 1;
    for (auto it = docks_.cbegin(); it != docks_.cend(); ++it) {
        const DockRow &row = *it->row;
        if (row.log || row.window) continue;
        QString title = dockTitle(row);
        const ui::ReceiverSession *s = it->shown;
        const bool receiver = s && s != logSession_;
        // Which receiver, on a dock pinned to it and, once there is more than one, on those
        // that act on it (settings, console, corrections): its number (the strip's, Ctrl+N) and
        // its colour on the tab. A number and not a name, and no colour on the docks that follow
        // the selection (the strip shows which that is): seven tabs beside the fix stay whole
        // at 1280x800 in Russian too (names cut them to "Реш…").
        const bool says = receiver && (it->pinned || (several && row.names));
        if (says) {
            const int n = int(sessions_.indexOf(const_cast<ui::ReceiverSession *>(s))) + 1;
            title = it->pinned ? tr("%1 · #%2 (pinned)").arg(title).arg(n)
                               : tr("%1 · #%2").arg(title).arg(n);
        }
        if (it.key()->windowTitle() != title) it.key()->setWindowTitle(title);
        const QColor colour = says ? s->colour() : QColor();
        if (it.key()->property("receiverColour").value<QColor>() != colour) {
            it.key()->setProperty("receiverColour", colour);
            it.key()->setWindowIcon(colour.isValid() ? swatch(colour) : QIcon());
        }
    }
    colourDockTabs();
}

void MainWindow::colourDockTabs() {
    // Qt's dock tabs show the title alone: the receiver's colour is put on them here, by the
    // title (unique in a tab group), and again whenever the tabs may have been made anew.
    QHash<QString, QColor> colours;
    for (auto it = docks_.cbegin(); it != docks_.cend(); ++it)
        colours.insert(it.key()->windowTitle(),
                       it.key()->property("receiverColour").value<QColor>());
    for (QTabBar *bar : findChildren<QTabBar *>(Qt::FindDirectChildrenOnly)) {
        for (int i = 0; i < bar->count(); ++i) {
            const QColor c = colours.value(bar->tabText(i));
            QIcon icon;
            if (c.isValid()) {
                auto found = tabSwatches_.find(c.rgb());
                if (found == tabSwatches_.end()) found = tabSwatches_.insert(c.rgb(), swatch(c));
                icon = *found;
            }
            if (bar->tabIcon(i).cacheKey() != icon.cacheKey()) bar->setTabIcon(i, icon);
        }
        keepTabsWhole(bar);
    }
}

void MainWindow::keepTabsWhole(QTabBar *bar) {
    // A group's docks are at least as wide as its tabs' whole titles (Russian ones are long;
    // the layout would otherwise give the room to the centre and cut them to "Реш…"), up to
    // 45 % of the window, so that the groups together still fit a laptop.
    const QFontMetrics fm(bar->font());
    int needed = 0;
    for (int i = 0; i < bar->count(); ++i)
        needed += fm.horizontalAdvance(bar->tabText(i)) + fm.height() * 2 +
                  (bar->tabIcon(i).isNull() ? 0 : bar->iconSize().width() + 4);
    needed = std::min(needed, width() * 45 / 100);
    for (auto it = docks_.cbegin(); it != docks_.cend(); ++it) {
        QDockWidget *d = it.key();
        // Never narrower than its own view needs (a narrower one wraps its texts taller).
        const int least = std::max(needed, d->minimumSizeHint().width());
        for (int i = 0; i < bar->count(); ++i)
            if (bar->tabText(i) == d->windowTitle() && d->minimumWidth() != least) {
                d->setMinimumWidth(least);
                break;
            }
    }
}

void MainWindow::updateReceivers() {
    if (!strip_) return;
    QList<ReceiverEntry> entries;
    for (ui::ReceiverSession *s : sessions_) {
        const session::ReceiverLink *lk = s->link();
        const auto st = lk->state();
        const bool live = st != session::ReceiverLink::State::Disconnected &&
                          st != session::ReceiverLink::State::Failed;
        ReceiverEntry e;
        e.name = s->name();
        e.colour = s->colour();
        e.selected = s == current_;
        // A receiver that stops talking says so before its link is opened again.
        const qint64 silentMs = lk->connection() ? lk->connection()->silentMs() : 0;
        const bool silent = st == session::ReceiverLink::State::Connected && silentMs >= 3000;
        if (silent) {
            e.status = tr("Silent for %1 s").arg(silentMs / 1000);
        } else if (st == session::ReceiverLink::State::Connected) {
            QStringList parts;
            if (lk->detectedBaud() > 0) parts << tr("%1 baud").arg(lk->detectedBaud());
            if (const Dialect *d = s->dialect())
                parts << QString::fromLatin1(d->displayName.data(), int(d->displayName.size()));
            const auto &c = s->counters();
            parts << tr("%1 sentences/s").arg(c.sentencesPerSecond, 0, 'f', 1);
            if (c.checksumErrors + c.decodeErrors > 0)
                parts << tr("%n error(s)", nullptr, int(c.checksumErrors + c.decodeErrors));
            if (c.skippedBytes >= 1024) // a line's worth at the start is not worth saying
                parts << tr("%1 KiB skipped").arg(c.skippedBytes / 1024);
            if (c.rtcmFrames)
                parts << tr("%n RTCM frame(s)", nullptr,
                            int(std::min<quint64>(c.rtcmFrames, INT_MAX)));
            e.status = parts.join(QStringLiteral(" · "));
        } else {
            e.status = lk->stateText();
            if (e.status.size() > 48) e.status = e.status.left(47) + QChar(0x2026);
        }
        e.tooltip = lk->stateText();
        const bool any = live && !silent && s->state()->epochCount() > 0;
        const FixType fix = any ? s->state()->state().epoch.fix : FixType::None;
        e.fix = silent ? tr("No data") : any ? style::fixTypeLabel(fix) : tr("No fix");
        e.fixColour = style::fixTypeColor(fix);
        entries << e;
    }
    strip_->setReceivers(entries);
    if (compare_)
        for (int i = 0; i < sessions_.size(); ++i) compare_->setName(i, sessions_[i]->name());
    strip_->setVisible(sessions_.size() > 1);
    for (int i = 0; i < receiverActions_.size() && i < sessions_.size(); ++i)
        receiverActions_[i]->setText(tr("&%1 %2").arg(i + 1).arg(sessions_[i]->name()));
    updateDockTitles();
}

void MainWindow::rebuildReceiverActions() {
    if (!receiverMenu_) return;
    qDeleteAll(receiverActions_);
    receiverActions_.clear();
    for (int i = 0; i < sessions_.size(); ++i) {
        ui::ReceiverSession *s = sessions_[i];
        QAction *a = receiverMenu_->addAction(swatch(s->colour()),
                                              tr("&%1 %2").arg(i + 1).arg(s->name()), this,
                                              [this, s] { selectReceiver(s); });
        a->setObjectName(QStringLiteral("selectReceiver%1").arg(i + 1));
        a->setCheckable(true);
        a->setChecked(s == current_);
        if (i < 9) a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + i)));
        receiverActions_ << a;
    }
}

void MainWindow::renameReceiver(ui::ReceiverSession *s) {
    if (!s) return;
    bool ok = false;
    const QString name = QInputDialog::getText(
            this, tr("Rename receiver"), tr("Name (empty: its model and port):"), QLineEdit::Normal,
            s->givenName().isEmpty() ? s->name() : s->givenName(), &ok);
    if (!ok) return;
    s->setGivenName(name);
    updateReceivers();
}

QStringList MainWindow::recordAll(const QString &folder, QString *why) {
    QStringList started, failed;
    std::vector<std::string> taken;
    const QDir dir(folder);
    for (ui::ReceiverSession *s : sessions_) {
        const QString path = dir.filePath(
                QString::fromStdString(link::recordingFileName(s->name().toStdString(), taken)));
        if (s->link()->startRecording(path))
            started << path;
        else
            failed << s->name();
    }
    if (why && !failed.isEmpty())
        *why = tr("Not recording %1: connect it first, and check %2 is writable.")
                       .arg(failed.join(QStringLiteral(", ")), folder);
    return started;
}

void MainWindow::saveReceivers() {
    QStringList sources, names, pins;
    for (const ui::ReceiverSession *s : sessions_) {
        sources << s->link()->source().toString();
        names << s->givenName();
    }
    // The docks pinned to a receiver, and the second docks, by the receiver's place in the list.
    for (auto it = docks_.cbegin(); it != docks_.cend(); ++it)
        if (it->pinned)
            pins << QStringLiteral("%1|%2|%3")
                            .arg(it.key()->objectName(), QLatin1String(it->row->name))
                            .arg(sessions_.indexOf(it->pinned.data()));
    settings_->setValue("receivers/sources", sources);
    settings_->setValue("receivers/names", names);
    settings_->setValue("receivers/docks", pins);
}

void MainWindow::restoreDocksOfReceivers() {
    if (!settings_) return;
    bool made = false;
    for (const QString &entry : settings_->value("receivers/docks").toStringList()) {
        const QStringList f = entry.split('|');
        if (f.size() != 3) continue;
        ui::ReceiverSession *s = sessions_.value(f[2].toInt());
        if (!s) continue;
        if (QDockWidget *d = dock(f[0]); d && docks_.contains(d)) {
            pinDock(d, s);
        } else if (duplicateDock(f[1], s, f[0])) {
            made = true;
        }
    }
    // The second docks where they were.
    if (made) restoreState(settings_->value("window/state").toByteArray());
}

void MainWindow::connectAtStart(const SourceSpec &spec) {
    connectReceiversAtStart(spec.valid() ? QList<SourceSpec>{spec} : QList<SourceSpec>{});
}

void MainWindow::connectReceiversAtStart(const QList<SourceSpec> &specs) {
    QList<SourceSpec> list = specs;
    QStringList names;
    bool restored = false;
    if (list.isEmpty() && settings_) {
        // The receivers of the last run, with the names they were given.
        const QStringList sources = settings_->value("receivers/sources").toStringList();
        const QStringList given = settings_->value("receivers/names").toStringList();
        for (int i = 0; i < sources.size(); ++i) {
            const SourceSpec s = SourceSpec::fromString(sources[i]);
            if (!s.valid()) continue;
            list << s;
            names << given.value(i);
        }
        restored = list.size() > 1 || !settings_->value("receivers/docks").toStringList().isEmpty();
        if (list.isEmpty()) {
            const SourceSpec last =
                    SourceSpec::fromString(settings_->value("connection/last").toString());
            if (last.valid()) list << last;
        }
    }
    // A first start: the first family the simulator plays.
    const QStringList simulated = transports_.names(SourceSpec::Kind::Simulator);
    if (list.isEmpty() && !simulated.isEmpty())
        list << SourceSpec{SourceSpec::Kind::Simulator, simulated.front()};
    if (list.isEmpty()) return;
    ui::ReceiverSession *first = current_;
    first->setGivenName(names.value(0));
    bar_->select(list.front());
    connectReceiver(first, list.front());
    for (int i = 1; i < list.size(); ++i) addReceiver(list[i])->setGivenName(names.value(i));
    selectReceiver(first);
    if (restored) restoreDocksOfReceivers();
}

} // namespace gnss::app
