// The main window: menus and docks present, start-up options, layout saved and restored, and the
// built-in simulated receiver reaching every model through the real connection path.
#include "bad_input_files.h"
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "config/settings_engine.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "gui/preferences_dialog.h"
#include "gui/startup_options.h"
#include "gui/window_start.h"
#include "logview/log_cursor.h"
#include "models/message_stats_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "models/signal_history_model.h"
#include "session/receiver_link.h"
#include "views/sky_plot_view.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

using gnss::app::parseStartupOptions;
using gnss::app::SourceSpec;

class TstMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    gnss::DialectRegistry registry_ = gnss::makeBuiltinRegistry();
    gnss::link::TransportFactory transports_ =
            gnss::app::makeTransportFactory(gnss::sim::builtinSimulators());

    std::unique_ptr<QSettings> settings() {
        return std::make_unique<QSettings>(dir_.filePath("settings.ini"), QSettings::IniFormat);
    }

    // Three epochs of a GPS receiver, written to the test's directory.
    QString writeSmallLog(const QString &name) {
        const QString log = dir_.filePath(name);
        QFile f(log);
        if (!f.open(QIODevice::WriteOnly)) return {};
        f.write("$GPGGA,092750.000,5321.6802,N,00630.3372,W,1,8,1.03,61.7,M,55.2,M,,*76\r\n"
                "$GPGSV,1,1,01,05,40,083,46*40\r\n"
                "$GPGGA,092751.000,5321.6802,N,00630.3372,W,1,8,1.03,61.7,M,55.2,M,,*77\r\n");
        return log;
    }

private slots:
    void mainWindowHasItsMenusAndDocks() {
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        QStringList titles;
        for (QAction *a : w.menuBar()->actions()) titles << a->text().remove('&');
        QCOMPARE(titles, (QStringList{"File", "Edit", "Receiver", "View", "Help"}));
        for (const char *d :
             {"skyDock", "fixDock", "signalDock", "satellitesDock", "consoleDock", "statsDock",
              "infoDock", "rtkDock", "chartsDock", "deviationDock", "attitudeDock"})
            QVERIFY2(w.dock(d), d);
    }

    // Edit → Preferences: the dialog refuses a bad baud list before anything changes; OK stores
    // everything and every view showing lengths, coordinates or times follows at once; a new
    // window starts with them; the language waits for the next start and says so.
    void preferencesChangeEveryView() {
        auto s = settings();
        s->clear();
        {
            gnss::app::MainWindow w(registry_, transports_, s.get());
            w.resize(1280, 800);
            w.show();
            w.connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, "nvs"});
            QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->state().epoch.altMsl.has_value(), 20000);
            const auto *alt = w.findChild<QLabel *>("fixAltMsl");
            QTRY_VERIFY(alt->text().endsWith(" m"));

            w.findChild<QAction *>("preferencesAction")->trigger();
            gnss::app::PreferencesDialog *dialog = nullptr;
            QTRY_VERIFY((dialog = w.findChild<gnss::app::PreferencesDialog *>()) &&
                        dialog->isVisible());
            auto *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
            auto *bauds = dialog->findChild<QLineEdit *>("prefBauds");
            auto *baudError = dialog->findChild<QLabel *>("prefBaudError");
            QVERIFY(ok->isEnabled());
            for (const char *bad : {"9600, 9600", "9600, 12345", "fast", ""}) {
                bauds->setText(bad);
                QVERIFY2(!ok->isEnabled(), bad);
                QVERIFY2(baudError->isVisibleTo(dialog) && !baudError->text().isEmpty(), bad);
            }
            bauds->setText("38400, 115200");
            QVERIFY(ok->isEnabled());
            auto choose = [dialog](const char *box, const QVariant &data) {
                auto *c = dialog->findChild<QComboBox *>(box);
                c->setCurrentIndex(c->findData(data));
                QVERIFY2(c->currentData() == data, box);
            };
            choose("prefUnits", int(gnss::ui::UnitSystem::Imperial));
            choose("prefCoordinates", int(gnss::ui::CoordinateFormat::DegreesMinutesSeconds));
            choose("prefTime", int(gnss::ui::TimeZoneChoice::Local));
            choose("prefLanguage", QString("ru"));
            QVERIFY(dialog->findChild<QLabel *>("prefLanguageNote")->isVisibleTo(dialog));
            ok->click();

            QTRY_VERIFY2(alt->text().endsWith(" ft"), qPrintable(alt->text()));
            QVERIFY(w.findChild<QLabel *>("fixLatitude")->text().contains(QChar(0x2033)));
            QVERIFY(w.findChild<QLabel *>("fixUtc")->text().contains("UTC+"));
            const auto *marks = w.findChild<QTableWidget *>("timeMarkTable");
            QCOMPARE(marks->horizontalHeaderItem(5)->text(), QString("Altitude MSL (ft)"));
            QCOMPARE(marks->horizontalHeaderItem(2)->text(), QString("Local time"));
            const auto *stats = w.findChild<gnss::ui::MessageStatsModel *>();
            QCOMPARE(stats->headerData(gnss::ui::MessageStatsModel::LastSeen, Qt::Horizontal)
                             .toString(),
                     QString("Last seen (local time)"));
            QCOMPARE(w.link()->baudCandidates(), (QList<int>{38400, 115200}));
            QVERIFY(w.statusBar()->currentMessage().contains("next start"));
            QCOMPARE(s->value("view/units").toString(), QString("imperial"));
            QCOMPARE(s->value("view/coordinates").toString(), QString("dms"));
            QCOMPARE(s->value("view/time").toString(), QString("local"));
            QCOMPARE(s->value("ui/language").toString(), QString("ru"));
            QCOMPARE(s->value("link/detectionBauds").toString(), QString("38400, 115200"));
        }
        {
            gnss::app::MainWindow w(registry_, transports_, s.get());
            QCOMPARE(w.preferences().display.units, gnss::ui::UnitSystem::Imperial);
            QCOMPARE(w.link()->baudCandidates(), (QList<int>{38400, 115200}));
            // The view's own coordinate box is the same preference.
            auto *box = w.findChild<QComboBox *>("coordinateFormat");
            QCOMPARE(box->currentIndex(), 2);
            box->setCurrentIndex(1);
            emit box->activated(1);
            QCOMPARE(w.preferences().display.coordinates,
                     gnss::ui::CoordinateFormat::DegreesMinutes);
            QCOMPARE(s->value("view/coordinates").toString(), QString("dm"));
        }
        s->clear();
    }

    void simulatedReceiverReachesTheModels() {
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        w.connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, "nvs"});
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->epochCount() >= 3, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(w.satelliteModel()->rowCount() > 5, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->state().epoch.lat.has_value(), 20000);
        QCOMPARE(w.link()->state(), gnss::session::ReceiverLink::State::Connected);
        const auto *fixLabel = w.findChild<QLabel *>("statusFix");
        QVERIFY(fixLabel);
    }

    // The connection bar's source that cannot be opened: the state line says what and why
    // (a misspelled port, a TCP source without its port, a log to replay that is missing or
    // whose index is someone else's file); none is retried: a log would not mend, a port that is
    // not there is chosen again when it is plugged in.
    void aSourceThatCannotBeOpenedIsSaidSo_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("words");
        using Kind = SourceSpec::Kind;
        QTest::newRow("a misspelled port") << int(Kind::Serial) << "/dev/ttyUSB-no-such"
                                           << "/dev/ttyUSB-no-such: No such file";
        QTest::newRow("TCP without a port") << int(Kind::Tcp) << "127.0.0.1"
                                            << "a TCP source is HOST:PORT";
        QTest::newRow("a missing log")
                << int(Kind::Replay) << dir_.filePath("missing.nmea") << "missing.nmea";
        QTest::newRow("a foreign index") << int(Kind::Replay) << dir_.filePath("foreign.nmea")
                                         << "line 1: not an index line";
    }
    void aSourceThatCannotBeOpenedIsSaidSo() {
        QFETCH(int, kind);
        QFETCH(QString, name);
        QFETCH(QString, words);
        QVERIFY(!gnss::test::writeUserFile(dir_, "foreign.nmea", gnss::test::kOneGga, "<xml>\n")
                         .isEmpty());
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        SourceSpec spec{SourceSpec::Kind(kind), name};
        spec.baud = 9600;
        w.link()->connectTo(spec);
        QTRY_VERIFY_WITH_TIMEOUT(w.link()->stateText().contains(words), 10000);
        QTest::qWait(200);
        const QString text = w.link()->stateText();
        QVERIFY2(text.contains(words), qPrintable(text));
        QVERIFY2(!text.contains("trying again"), qPrintable(text));
        QCOMPARE(w.link()->state(), gnss::session::ReceiverLink::State::Failed);
        w.link()->disconnectFromSource();
    }

    void skyPlotDrawsTheReceiversElevationMask() {
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        w.connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, "nvs"});
        auto *engine = w.findChild<gnss::config::SettingsEngine *>();
        QVERIFY(engine);
        QTRY_VERIFY_WITH_TIMEOUT(engine->receiverValue("rtk.ELGPS").has_value(), 15000);
        auto *sky = w.findChild<gnss::ui::SkyPlotView *>("skyPlot");
        QCOMPARE(sky->elevationMask(),
                 QString::fromStdString(*engine->receiverValue("rtk.ELGPS")).toDouble());
    }

    void closingWithACommandInFlightIsSafe() {
        auto s = settings();
        auto w = std::make_unique<gnss::app::MainWindow>(registry_, transports_, s.get());
        w->show();
        w->connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, "nvs"});
        QString why;
        QVERIFY2(w->link()->send("$PNVGVER*4E", &why), qPrintable(why));
        w.reset(); // the command is still waiting for its answer
    }

    void layoutAndLastConnectionAreRestored() {
        {
            auto s = settings();
            gnss::app::MainWindow w(registry_, transports_, s.get());
            w.show();
            w.connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, "nmea"});
            w.dock("consoleDock")->hide();
            w.saveLayout();
        }
        auto s = settings();
        QCOMPARE(s->value("connection/last").toString(), QString("sim:nmea"));
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        QVERIFY(w.dock("consoleDock")->isHidden());
        QVERIFY(w.dock("skyDock")->isVisible());
        w.connectAtStart({}); // no source given: the last one
        QCOMPARE(w.link()->source().toString(), QString("sim:nmea"));
    }

    // `gnss-workbench LOG --show-dock sky`: opening a log brings the log's docks forward (the
    // track beside the sky plot); the dock asked for on the command line must still be the one in
    // front, and an unknown one is refused before anything is opened.
    void showDockIsInFrontAfterALogOpens() {
        const QString log = writeSmallLog("show-dock.nmea");
        QVERIFY(!log.isEmpty());
        QString err;
        auto o = parseStartupOptions({"gnss-workbench", log, "--show-dock", "sky"},
                                     gnss::app::simulatedDialects(gnss::sim::builtinSimulators()),
                                     err);
        QVERIFY2(o, qPrintable(err));
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(gnss::app::startWindow(w, *o), QString());
        QVERIFY(w.windowTitle().startsWith("show-dock.nmea"));
        QTRY_VERIFY(!w.dock("skyDock")->visibleRegion().isEmpty());
        QVERIFY(w.dock("logTrackDock")->isVisible());
        QVERIFY(w.dock("logTrackDock")->visibleRegion().isEmpty());

        o->showDock = "nosuch";
        gnss::app::MainWindow other(registry_, transports_, s.get());
        const QString refused = gnss::app::startWindow(other, *o);
        QVERIFY(refused.contains("nosuch"));
        QVERIFY(!other.windowTitle().startsWith("show-dock.nmea"));
    }

    // The log's docks and timeline show only "no log open" without a log: a layout saved with a
    // log open must not bring them back empty at the next start, nor keep them after the log
    // closes; the next log shows them where they were.
    void logDocksGoAwayWithoutALog() {
        const QString log = writeSmallLog("docks.nmea");
        QVERIFY(!log.isEmpty());
        const char *const logDocks[] = {"logEventsDock", "logSummaryDock", "logChartsDock",
                                        "logTrackDock"};
        // A layout of its own (the suite's other tests close docks and save).
        auto s = std::make_unique<QSettings>(dir_.filePath("docks.ini"), QSettings::IniFormat);
        {
            gnss::app::MainWindow w(registry_, transports_, s.get());
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.openLog(log);
            for (const char *d : logDocks) QVERIFY2(!w.dock(d)->isHidden(), d);
            QVERIFY(w.tabifiedDockWidgets(w.dock("skyDock")).contains(w.dock("logTrackDock")));
            w.saveLayout(); // as when the window closes with the log open
        }
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *timeline = w.findChild<QToolBar *>("timelineBar");
        QVERIFY(timeline);
        for (const char *d : logDocks) QVERIFY2(w.dock(d)->isHidden(), d);
        QVERIFY(timeline->isHidden());
        QTRY_VERIFY(!w.dock("skyDock")->visibleRegion().isEmpty());
        QTRY_VERIFY(!w.dock("consoleDock")->visibleRegion().isEmpty());

        w.openLog(log);
        for (const char *d : logDocks) QVERIFY2(!w.dock(d)->isHidden(), d);
        QVERIFY(!timeline->isHidden());
        QVERIFY(w.tabifiedDockWidgets(w.dock("skyDock")).contains(w.dock("logTrackDock")));
        QTRY_VERIFY(!w.dock("logTrackDock")->visibleRegion().isEmpty());
        QTRY_VERIFY(!w.dock("logChartsDock")->visibleRegion().isEmpty());

        w.closeLog();
        for (const char *d : logDocks) QVERIFY2(w.dock(d)->isHidden(), d);
        QVERIFY(timeline->isHidden());
        QTRY_VERIFY(!w.dock("skyDock")->visibleRegion().isEmpty());
        w.openLog(log);
        for (const char *d : logDocks) QVERIFY2(!w.dock(d)->isHidden(), d);
    }

    // The log's signal history covers the whole log, then the range selected on the timeline,
    // then the whole log again when the range is cleared.
    void logSignalHistoryFollowsTheRange() {
        const QString log = dir_.filePath("history.nmea");
        {
            auto rx = gnss::sim::builtinSimulators().make("nvs", {});
            QFile f(log);
            QVERIFY(f.open(QIODevice::WriteOnly));
            for (int s = 0; s < 300; ++s) {
                rx->advance(1.0);
                f.write(QByteArray::fromStdString(rx->takeOutput()));
            }
        }
        auto s = std::make_unique<QSettings>(dir_.filePath("history.ini"), QSettings::IniFormat);
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.openLog(log);
        auto history = [&w] { return &w.session()->signalHistory()->history(); };
        QTRY_VERIFY_WITH_TIMEOUT(history()->epochs() >= 299, 10000);
        QVERIFY(!history()->series().empty());
        gnss::ui::LogCursor *cursor = w.logViewer()->cursor();
        QVERIFY(cursor->epochCount() >= 299);
        cursor->setRange(100, 149);
        QTRY_COMPARE_WITH_TIMEOUT(history()->epochs(), std::uint64_t(50), 10000);
        QVERIFY(history()->newestMs() - history()->oldestMs() <= 49'000);
        cursor->clearRange();
        QTRY_VERIFY_WITH_TIMEOUT(history()->epochs() >= 299, 10000);
    }

    void startupOptionsParse() {
        QString err;
        auto o = parseStartupOptions({"gnss-workbench", "--sim", "nvs", "--screenshot",
                                      "/tmp/x.png", "--quit-after", "2.5"},
                                     gnss::app::simulatedDialects(gnss::sim::builtinSimulators()),
                                     err);
        QVERIFY2(o, qPrintable(err));
        QCOMPARE(o->sim, QString("nvs"));
        QCOMPARE(o->quitAfter, 2.5);
        o = parseStartupOptions({"gnss-workbench", "--port", "/dev/ttyUSB0", "--baud", "115200"},
                                gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err);
        QVERIFY(o);
        QCOMPARE(o->baud, 115200);
        // "auto", the default --help names, is accepted as such (0: detect).
        o = parseStartupOptions({"gnss-workbench", "--port", "/dev/ttyUSB0", "--baud", "auto"},
                                gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err);
        QVERIFY2(o, qPrintable(err));
        QCOMPARE(o->baud, 0);
        QCOMPARE(SourceSpec::fromString("serial:/dev/ttyUSB0@115200").baud, 115200);
        QCOMPARE(SourceSpec::fromString("tcp:localhost:5000").name, QString("localhost:5000"));
        // gpsd: the URL form or the bare HOST[:PORT][/DEVICE]; the name is kept without scheme.
        o = parseStartupOptions({"gnss-workbench", "--gpsd", "gpsd://localhost:2947/dev/ttyACM0"},
                                gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err);
        QVERIFY2(o, qPrintable(err));
        QCOMPARE(o->gpsd, QString("localhost:2947/dev/ttyACM0"));
        o = parseStartupOptions(
                {"gnss-workbench", "--gpsd", "localhost", "--show-dock", "settings"},
                gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err);
        QVERIFY2(o, qPrintable(err));
        QCOMPARE(o->gpsd, QString("localhost"));
        QCOMPARE(o->showDock, QString("settings"));
    }

    void showDockRaisesADockByItsShortName() {
        auto s = settings();
        gnss::app::MainWindow w(registry_, transports_, s.get());
        w.show();
        QVERIFY(w.dockNames().contains("settings"));
        QVERIFY(w.dockNames().contains("console"));
        QVERIFY(w.showDock("settings"));
        // In front of its tab group: the current tab of the bar that holds it.
        auto currentTabOf = [&w](const QString &title) {
            for (QTabBar *bar : w.findChildren<QTabBar *>())
                for (int i = 0; i < bar->count(); ++i)
                    if (bar->tabText(i) == title) return bar->tabText(bar->currentIndex());
            return QString();
        };
        QTRY_COMPARE(currentTabOf("Settings"), QString("Settings"));
        QVERIFY(w.showDock("fix"));
        QTRY_COMPARE(currentTabOf("Settings"), QString("Fix"));
        QVERIFY(!w.showDock("nosuch"));
    }

    void severalSourcesAreReceiversInTheOrderGiven() {
        QString err;
        const auto o = parseStartupOptions(
                {"x", "--port", "/dev/ttyUSB0", "--sim", "geostar", "--tcp", "127.0.0.1:5000",
                 "--port=/dev/ttyUSB1", "--baud", "57600", "--gpsd",
                 "gpsd://localhost/dev/ttyACM0"},
                gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err);
        QVERIFY2(o, qPrintable(err));
        QStringList given;
        for (const SourceSpec &s : o->sources) given << s.toString();
        QCOMPARE(given,
                 (QStringList{"serial:/dev/ttyUSB0@57600", "sim:geostar", "tcp:127.0.0.1:5000",
                              "serial:/dev/ttyUSB1@57600", "gpsd://localhost/dev/ttyACM0"}));
        // The first of each kind stays where it was.
        QCOMPARE(o->port, QString("/dev/ttyUSB0"));
        QCOMPARE(o->gpsd, QString("localhost/dev/ttyACM0"));
    }

    void badStartupOptionsAreRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("unknown sim") << QStringList{"x", "--sim", "garmin"};
        QTest::newRow("a log and a source") << QStringList{"x", "log.nmea", "--sim", "nvs"};
        QTest::newRow("a second unknown sim")
                << QStringList{"x", "--sim", "nvs", "--sim", "garmin"};
        QTest::newRow("bad baud") << QStringList{"x", "--baud", "fast"};
        QTest::newRow("unknown option") << QStringList{"x", "--frobnicate"};
        QTest::newRow("bad gpsd port") << QStringList{"x", "--gpsd", "localhost:0"};
        QTest::newRow("a second bad gpsd")
                << QStringList{"x", "--gpsd", "localhost", "--gpsd", "localhost:0"};
    }
    void badStartupOptionsAreRefused() {
        QFETCH(QStringList, args);
        QString err;
        QVERIFY(!parseStartupOptions(
                args, gnss::app::simulatedDialects(gnss::sim::builtinSimulators()), err));
        QVERIFY(!err.isEmpty());
    }
};

QTEST_MAIN(TstMainWindow)
#include "tst_main_window.moc"
