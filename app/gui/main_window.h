#pragma once
// MainWindow: menus, docks, the connection bar, the receivers strip and the status bar. It holds
// the receiver sessions (ui::ReceiverSession: one per receiver) and gives each dock the session it
// shows: the selected receiver's (Ctrl+1…9), or the one it is pinned to; its docks are the rows of
// dock_table.h, each made again for another session. It does not decode or draw.
#include "gui/dock_table.h"
#include "gui/preferences.h"
#include "link/source_spec.h"
#include "sites/site_store.h"

#include <QHash>
#include <QIcon>
#include <QList>
#include <QMainWindow>
#include <QPointer>

#include <atomic>
#include <memory>
#include <span>

class QLabel;
class QSettings;
class QDockWidget;
class QToolBar;
class QTabBar;
class QMenu;
class QThread;

namespace gnss {
class DialectRegistry;
struct Dialect;
struct SettingDef;
namespace link {
class PortWatcher;
class TransportFactory;
} // namespace link
namespace session {
class ReceiverLink;
}
namespace ui {
class CompareModel;
class ConsoleView;
class ReceiverSession;
class ReceiverStateModel;
class SatelliteModel;
class AccuracyPanel;
class SkyPlotView;
class RtkView;
class ChartsView;
} // namespace ui
} // namespace gnss

namespace gnss::app {

using link::SourceSpec;

class ConnectionBar;
class CorrectionsController;
class QualificationController;
class ServeController;
class ReceiversStrip;
class LogPlayer;
class LogViewer;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `transports` makes the links the connection bar offers; `settings` keeps the layout, the
    // last connection and view options between runs.
    MainWindow(const DialectRegistry &registry, const link::TransportFactory &transports,
               QSettings *settings, QWidget *parent = nullptr);
    ~MainWindow() override;

    // The receivers' sessions, in the order of the receivers strip (Ctrl+1…9).
    const QList<ui::ReceiverSession *> &sessions() const { return sessions_; }
    // What the docks that follow the selection show: the open log's session while a log is
    // open, else the selected receiver's.
    ui::ReceiverSession *session() const;
    // The selected receiver: the one the connection bar, the Receiver menu and the status bar
    // are about.
    ui::ReceiverSession *selectedSession() const { return current_; }
    // The selected receiver's link; the shown session's state and satellites.
    session::ReceiverLink *link() const;
    ui::ReceiverStateModel *stateModel() const;
    ui::SatelliteModel *satelliteModel() const;
    // A receiver's corrections (each its own stream, which goes on feeding it whatever the docks
    // show); null: the selected receiver's.
    CorrectionsController *corrections(ui::ReceiverSession *s = nullptr);
    // The receivers compared (the Compare dock's model).
    ui::CompareModel *comparison() const { return compare_; }
    // Time-to-first-fix campaigns and accuracy on the receivers (the Qualification dock's).
    QualificationController *qualification();
    // The Serve dock's servers (made on first use).
    ServeController *serving();
    const sites::SiteStore &siteStore() const { return siteStore_; }
    QDockWidget *dock(const QString &objectName) const;
    // The docks by short name ("settings" for settingsDock), for --show-dock.
    QStringList dockNames() const;
    // Shows the dock named so and puts it in front of its tab group; false for an unknown name.
    bool showDock(const QString &name);

    // Connects to `spec`, or (invalid spec) to the receivers of the last run, or to the
    // simulated NV08C-RTK the first time.
    void connectAtStart(const SourceSpec &spec);
    // Several receivers at once (the command line's repeated sources); none: as above.
    void connectReceiversAtStart(const QList<SourceSpec> &specs);

    // Another receiver, connected to `spec` (invalid: left unconnected) and selected.
    ui::ReceiverSession *addReceiver(const SourceSpec &spec);
    // Closes a receiver (its link, recording and docks pinned to it); the last one is only
    // disconnected. The others keep running.
    void closeReceiver(ui::ReceiverSession *s);
    // The docks that follow the selection show `s` from now on; its source is in the bar.
    void selectReceiver(ui::ReceiverSession *s);
    // Pins a dock to a receiver (null: it follows the selection again).
    void pinDock(QDockWidget *dock, ui::ReceiverSession *s);
    ui::ReceiverSession *dockSession(QDockWidget *dock) const;
    ui::ReceiverSession *pinnedSession(QDockWidget *dock) const;
    // A second dock of the row named so (`fix`), pinned to `s`: two Fix docks, base and rover.
    // `objectName`: the dock's (to restore a layout); empty: the next free one (fixDock-2).
    QDockWidget *duplicateDock(const QString &name, ui::ReceiverSession *s,
                               const QString &objectName = {});
    // File → Record with several receivers: one file per receiver in `folder`, named after it.
    // Returns the files started; `why` says what failed.
    QStringList recordAll(const QString &folder, QString *why = nullptr);
    void saveLayout();
    void restoreLayout();

    // The preferences in force; setting them stores them and every view follows at once (a
    // new language at the next start).
    const Preferences &preferences() const { return prefs_; }
    void setPreferences(const Preferences &prefs);
    // Opens the Preferences dialog (window-modal; OK applies it).
    void openPreferences();

    // The offline log viewer: opens a log (the live link is closed), shows the timeline and the
    // log's docks; every dock follows the timeline's cursor.
    // `at`: where the cursor goes once indexed ("10:42:00", "#1200"; empty: the start).
    void openLog(const QString &path, const QString &at = {});
    void closeLog();
    LogViewer *logViewer() const { return logViewer_; }
    LogPlayer *logPlayer() const { return logPlayer_; }
    // File → Play Out: the dialog that sends the log to other software.
    void openPlayOut();
    // Asks where, then exports the selected range (or the whole log) in the format of the
    // file's suffix.
    void exportLog();
    QStringList recentLogs() const;

signals:
    void displayPrefsChanged(const gnss::ui::DisplayPrefs &prefs);
    // A receiver added or closed.
    void receiversChanged();

protected:
    void closeEvent(QCloseEvent *e) override;
    void dragEnterEvent(QDragEnterEvent *e) override;
    void dropEvent(QDropEvent *e) override;

private:
    friend std::span<const DockRow> dockRows();

    struct DockBinding {
        const DockRow *row = nullptr;
        QPointer<ui::ReceiverSession> shown;
        QPointer<ui::ReceiverSession> pinned; // null: follows the selection
        bool duplicate = false;
    };
    void createDocks();
    QDockWidget *makeDock(const DockRow &row, const QString &objectName, ui::ReceiverSession &s);
    // Makes the dock's view again for `s` (the view's own choices carried over).
    void bindDock(QDockWidget *dock, ui::ReceiverSession *s);
    void rebindFollowingDocks();
    void updateDockTitles();
    void dockMenu(QDockWidget *dock, const QPoint &globalPos);
    ui::ReceiverSession *newSession();
    void wireSession(ui::ReceiverSession *s);
    void connectReceiver(ui::ReceiverSession *s, const SourceSpec &spec);
    // The serial port asked for is another receiver's already (a second open would only meet
    // its lock): that receiver is selected and the status bar says so; false when it is free.
    bool portTakenByAnother(const SourceSpec &spec, const ui::ReceiverSession *asking);
    void refreshBar();
    void updateReceivers();
    void rebuildReceiverActions();
    void renameReceiver(ui::ReceiverSession *s);
    // A label that tells the receivers apart in titles: the short name, with the place when two
    // share it.
    QString receiverLabel(const ui::ReceiverSession *s) const;
    // Whether a dock's view holds work begun for its receiver (edits not applied, a command
    // typed): such a dock keeps its receiver when the selection changes.
    static bool holdsWork(const QWidget *view);
    // Puts each dock's receiver colour on its tab (Qt's dock tabs show no icon of their own).
    void colourDockTabs();
    void keepTabsWhole(QTabBar *bar);
    void saveReceivers();
    QList<SourceSpec> restoreReceivers();
    void restoreDocksOfReceivers();
    void createMenus();
    void createStatusBar();
    void wireConnection();
    // Units, coordinate format and time zone (Preferences) reach every view that shows them.
    template <class View> void followDisplayPrefs(View *view) {
        view->setDisplayPrefs(prefs_.display);
        connect(this, &MainWindow::displayPrefsChanged, view, &View::setDisplayPrefs);
    }
    // The docks' views (dock_table.h), each for the session it shows.
    QWidget *makeSkyPlot(ui::ReceiverSession &s);
    QWidget *makeFix(ui::ReceiverSession &s);
    QWidget *makeSignalLevels(ui::ReceiverSession &s);
    QWidget *makeSatellites(ui::ReceiverSession &s);
    QWidget *makeConsole(ui::ReceiverSession &s);
    QWidget *makeStatistics(ui::ReceiverSession &s);
    QWidget *makeReceiverInfo(ui::ReceiverSession &s);
    QWidget *makeRtk(ui::ReceiverSession &s);
    QWidget *makeCharts(ui::ReceiverSession &s);
    QWidget *makeDeviation(ui::ReceiverSession &s);
    QWidget *makeAttitude(ui::ReceiverSession &s);
    QWidget *makeCorrections(ui::ReceiverSession &s);
    QWidget *makeSettings(ui::ReceiverSession &s);
    QWidget *makeSignalHistory(ui::ReceiverSession &s);
    QWidget *makeCompare(ui::ReceiverSession &s);
    QWidget *makeQualification(ui::ReceiverSession &s);
    QWidget *makeBaseStation(ui::ReceiverSession &s);
    QWidget *makeServe(ui::ReceiverSession &s);
    void useSites(ui::AccuracyPanel *panel);
    void updateCompareReceivers();
    QWidget *makeLogTrack(ui::ReceiverSession &s);
    QWidget *makeLogSummary(ui::ReceiverSession &s);
    QWidget *makeLogCharts(ui::ReceiverSession &s);
    QWidget *makeLogEvents(ui::ReceiverSession &s);
    // The sky plot's elevation mask: the dialect's default, then the receiver's own value.
    void followElevationMask(ui::ReceiverSession &s, ui::SkyPlotView *sky);
    void updateStatus();
    void applyTheme(const QString &theme);
    void toggleRecording(bool on);
    void createLogViewer();
    void wireLogConsole(ui::ConsoleView *view);
    // The open log's signal history (C/N0 over the whole log), on a worker.
    void scanLogSignals();
    void stopLogSignalScan();
    void putLogViewAway();
    void createLogMenu(QMenu *file);
    void rememberLog(const QString &path);
    void updateRecentMenu();
    static const SettingDef *elevationMaskSetting(const Dialect *d);

    const DialectRegistry &registry_;
    const link::TransportFactory &transports_;
    QSettings *settings_;
    link::PortWatcher *ports_ = nullptr;
    QList<ui::ReceiverSession *> sessions_;
    ui::ReceiverSession *current_ = nullptr;    // the selected receiver
    ui::ReceiverSession *logSession_ = nullptr; // the open log's models
    int sessionsMade_ = 0;
    QHash<QDockWidget *, DockBinding> docks_;
    ui::CompareModel *compare_ = nullptr;
    QualificationController *qualification_ = nullptr;
    ServeController *serve_ = nullptr;
    // The user's site list (references for the accuracy, shared with gnss-cli sites).
    sites::SiteStore siteStore_;
    QHash<const ui::ReceiverSession *, QPointer<CorrectionsController>> corrections_;
    QHash<QRgb, QIcon> tabSwatches_; // one icon per colour: a tab's is compared by its key
    ConnectionBar *bar_ = nullptr;
    ReceiversStrip *strip_ = nullptr;
    QMenu *receiverMenu_ = nullptr;
    QList<QAction *> receiverActions_;
    bool skyTracks_ = false;
    QStringList consoleHistory_;
    QMenu *viewMenu_ = nullptr;
    QList<QAction *> themeActions_;
    Preferences prefs_;
    QString startLanguage_; // the language the program started in
    QAction *recordAction_ = nullptr;
    LogViewer *logViewer_ = nullptr;
    LogPlayer *logPlayer_ = nullptr;
    QAction *playOutAction_ = nullptr;
    QToolBar *timelineBar_ = nullptr;
    QMenu *recentMenu_ = nullptr;
    QAction *exportAction_ = nullptr, *closeLogAction_ = nullptr;
    bool logDocksShown_ = false;
    QThread *logScan_ = nullptr;
    std::shared_ptr<std::atomic<bool>> logScanCancel_;
    bool logSignalsScanned_ = false;
    bool logDocksPlaced_ = false; // the log's docks have a place in the layout (shown before)
    QLabel *stateLabel_ = nullptr, *dialectLabel_ = nullptr, *rateLabel_ = nullptr,
           *errorLabel_ = nullptr, *fixLabel_ = nullptr, *recordLabel_ = nullptr;
    QByteArray defaultState_;
};

} // namespace gnss::app
