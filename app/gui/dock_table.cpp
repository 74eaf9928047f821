#include "gui/dock_table.h"

#include "gui/main_window.h"

#include <QCoreApplication>

namespace gnss::app {

namespace {
constexpr const char *kContext = "gnss::app::MainWindow";
} // namespace

// In the order of the View menu and of each group's tabs. The groups: the sky plot's on the
// left (the signal levels below it; the receiver's identity beside the sky), the fix's on the
// right (the settings form there, where it is tall), the console's at the bottom. With several
// receivers the settings, console and corrections tabs carry a number and a colour: the fix's
// group holds six tabs and has 55% of the width at the first start, so that they stay whole. The
// log's docks join the sky plot's group (track, range statistics) and the console's (whole-log
// charts, events, a wide list): the live groups keep the tabs they have, so that every tab's title
// stays whole on a laptop in every language (ten tabs beside the fix were cut to "Ре…", "Поп…" in
// Russian at 1280x800).
std::span<const DockRow> dockRows() {
    using M = MainWindow;
    constexpr auto L = Qt::LeftDockWidgetArea, R = Qt::RightDockWidgetArea,
                   B = Qt::BottomDockWidgetArea;
    static const DockRow rows[] = {
            {"sky", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Sky plot"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Sky plot"), L, "left", nullptr, true,
             false, &M::makeSkyPlot},
            {"signal", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Signal levels"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Signal levels"), L, nullptr, "sky", false,
             false, &M::makeSignalLevels},
            {"deviation", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Deviation"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Deviation"), L, "left", nullptr, false,
             false, &M::makeDeviation},
            {"fix", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Fix"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Fix and position"), R, "right", nullptr,
             true, false, &M::makeFix},
            {"rtk", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "RTK"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "RTK"), R, "right", nullptr, false, false,
             &M::makeRtk},
            {"corrections", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Corrections"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Corrections (RTCM)"), R, "right", nullptr,
             false, false, &M::makeCorrections, false, true},
            {"info", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Receiver"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Receiver information"), L, "left", nullptr,
             false, false, &M::makeReceiverInfo},
            {"satellites", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Satellites"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Satellites"), R, "right", nullptr, false,
             false, &M::makeSatellites},
            {"attitude", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Attitude"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Attitude and time marks"), R, "right",
             nullptr, false, false, &M::makeAttitude},
            {"settings", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Settings"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Receiver settings"), R, "right", nullptr,
             false, false, &M::makeSettings, false, true},
            {"console", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Console"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Console"), B, "bottom", nullptr, true,
             false, &M::makeConsole, false, true},
            {"stats", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Statistics"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Message statistics"), B, "bottom", nullptr,
             false, false, &M::makeStatistics},
            {"charts", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Charts"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Charts"), B, "bottom", nullptr, false,
             false, &M::makeCharts},
            {"history", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Signal history"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Signal history and C/N0 map"), B, "bottom",
             nullptr, false, false, &M::makeSignalHistory},
            {"compare", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Compare"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Compare receivers"), B, "bottom", nullptr,
             false, false, &M::makeCompare, true},
            {"qualify", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Qualification"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Qualification (TTFF, accuracy)"), B,
             "bottom", nullptr, false, false, &M::makeQualification, true, false, true},
            {"base", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Base"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Base station"), R, "right", nullptr, false,
             false, &M::makeBaseStation, false, true, true},
            {"serve", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Serve"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Serve streams (NTRIP caster, TCP)"), B,
             "bottom", nullptr, false, false, &M::makeServe, true, false, true},
            {"logTrack", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Track"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Track (whole log)"), L, "left", nullptr,
             true, true, &M::makeLogTrack},
            {"logSummary", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Log statistics"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Log statistics (range)"), R, "left",
             nullptr, false, true, &M::makeLogSummary},
            {"logCharts", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Log charts"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Log charts (whole log)"), B, "bottom",
             nullptr, true, true, &M::makeLogCharts},
            {"logEvents", QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Events"),
             QT_TRANSLATE_NOOP("gnss::app::MainWindow", "Log events"), R, "bottom", nullptr, false,
             true, &M::makeLogEvents},
    };
    return rows;
}

const DockRow *findDockRow(const QString &name) {
    const QString n = name.endsWith(QLatin1String("Dock")) ? name.chopped(4) : name;
    for (const DockRow &r : dockRows())
        if (n == QLatin1String(r.name)) return &r;
    return nullptr;
}

QString dockObjectName(const DockRow &row) {
    return QLatin1String(row.name) + QLatin1String("Dock");
}

QString dockTitle(const DockRow &row) {
    return QCoreApplication::translate(kContext, row.title);
}

QString dockFullTitle(const DockRow &row) {
    return QCoreApplication::translate(kContext, row.fullTitle);
}

} // namespace gnss::app
