#pragma once
// MainWindow: menus, docks, the connection bar and the status bar. It holds the receiver
// sessions (ui::ReceiverSession: one per receiver, one for now) and gives each dock the session
// it shows; its docks are the rows of dock_table.h. It does not decode or draw.
#include "gui/dock_table.h"
#include "gui/preferences.h"
#include "link/source_spec.h"

#include <QList>
#include <QMainWindow>

#include <span>

class QLabel;
class QSettings;
class QDockWidget;
class QToolBar;
class QMenu;

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
class ConsoleView;
class ReceiverSession;
class ReceiverStateModel;
class SatelliteModel;
class SkyPlotView;
class RtkView;
class ChartsView;
} // namespace ui
} // namespace gnss

namespace gnss::app {

using link::SourceSpec;

class ConnectionBar;
class CorrectionsController;
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

    // The receivers' sessions (one for now) and the one the docks show.
    const QList<ui::ReceiverSession *> &sessions() const { return sessions_; }
    ui::ReceiverSession *session() const { return session_; }
    // The shown session's link, state and satellites.
    session::ReceiverLink *link() const;
    ui::ReceiverStateModel *stateModel() const;
    ui::SatelliteModel *satelliteModel() const;
    CorrectionsController *corrections() const { return corrections_; }
    QDockWidget *dock(const QString &objectName) const;
    // The docks by short name ("settings" for settingsDock), for --show-dock.
    QStringList dockNames() const;
    // Shows the dock named so and puts it in front of its tab group; false for an unknown name.
    bool showDock(const QString &name);

    // Connects to `spec`, or (invalid spec) to the last source used, or to the simulated
    // NV08C-RTK the first time.
    void connectAtStart(const SourceSpec &spec);
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

protected:
    void closeEvent(QCloseEvent *e) override;
    void dragEnterEvent(QDragEnterEvent *e) override;
    void dropEvent(QDropEvent *e) override;

private:
    friend std::span<const DockRow> dockRows();

    void createDocks();
    void createMenus();
    void createStatusBar();
    void wireConnection();
    // Units, coordinate format and time zone (Preferences) reach every view that shows them.
    template <class View> void followDisplayPrefs(View *view) {
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
    void wireLogConsole();
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
    ui::ReceiverSession *session_ = nullptr; // the one the docks show
    session::ReceiverLink *link_ = nullptr;  // its link
    CorrectionsController *corrections_ = nullptr;
    ConnectionBar *bar_ = nullptr;
    ui::SkyPlotView *sky_ = nullptr;
    ui::RtkView *rtk_ = nullptr;
    ui::ChartsView *charts_ = nullptr;
    ui::ConsoleView *consoleView_ = nullptr;
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
    bool logDocksPlaced_ = false; // the log's docks have a place in the layout (shown before)
    QLabel *stateLabel_ = nullptr, *dialectLabel_ = nullptr, *rateLabel_ = nullptr,
           *errorLabel_ = nullptr, *fixLabel_ = nullptr, *recordLabel_ = nullptr;
    QByteArray defaultState_;
};

} // namespace gnss::app
