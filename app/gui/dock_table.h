#pragma once
// The main window's docks, one row each: what creating them, laying them out, the View menu,
// restoring a saved layout (by object name) and `--show-dock NAME` all read.
#include <QString>
#include <QWidget>

#include <span>

namespace gnss::ui {
class ReceiverSession;
}

namespace gnss::app {

class MainWindow;

struct DockRow {
    // The short name (`--show-dock sky`); the dock's object name is this + "Dock" (skyDock).
    const char *name;
    // The tab's title (short: whole at 1280 px in every language) and the View menu's, both
    // translated in MainWindow's context.
    const char *title;
    const char *fullTitle;
    Qt::DockWidgetArea area;
    // Docks of one group share a tab bar, in table order (null: a place of its own).
    const char *tabGroup;
    // Split below this dock rather than tabbed (null: not split).
    const char *below = nullptr;
    // In front of its tab group in the first layout.
    bool front = false;
    // One of the log viewer's: hidden while no log is open, tabbed into its group when the first
    // log opens, put away when it closes.
    bool log = false;
    // Makes the dock's view for the session it shows (and wires it).
    QWidget *(MainWindow::*make)(ui::ReceiverSession &session) = nullptr;
    // About every receiver of the window (the comparison), not the one selected: never made
    // again for another session, never pinned.
    bool window = false;
    // Acts on its receiver (the settings form, the console, corrections): its title names the
    // receiver whenever there are several.
    bool names = false;
    // Put away in the first layout (a tool for some users: View menu, --show-dock), so that the
    // groups' tabs stay whole on a laptop; shown, it joins its group.
    bool putAway = false;
};

std::span<const DockRow> dockRows();
// The row of `name` ("sky" or "skyDock"); null for an unknown name.
const DockRow *findDockRow(const QString &name);
QString dockObjectName(const DockRow &row);
QString dockTitle(const DockRow &row);
QString dockFullTitle(const DockRow &row);

} // namespace gnss::app
