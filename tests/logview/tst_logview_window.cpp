// The offline log viewer in the real main window at laptop size (1280x800, offscreen): a log with
// known faults is opened, the timeline, events, statistics, whole-log charts and track appear,
// and every live dock shows exactly what a front-to-back decode has at the cursor, however the
// cursor moves (keys, the strip, an event, a typed time, the track, the chart, playing). Bad
// files say so in the status bar; exports write what the engine writes.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "compare/accuracy.h"
#include "gui/log_player.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "gui/play_out_dialog.h"
#include "gui/startup_options.h"
#include "log_generator.h"
#include "logview/log_events_view.h"
#include "logview/log_summary_view.h"
#include "logview/timeline_panel.h"
#include "logview/timeline_strip.h"
#include "logview/whole_log_panels.h"
#include "logview_files.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "qualify/accuracy_panel.h"
#include "qualify/qualify_plots.h"
#include "raw_pty.h"
#include "scenario_log.h"
#include "tab_titles.h"
#include "views/console_view.h"

#include <QCheckBox>
#include <QDeadlineTimer>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabBar>
#include <QTableView>
#include <QTableWidget>
#include <QTcpServer>
#include <QTcpSocket>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>
#include <chrono>
#include <random>
#include <thread>
#include <zlib.h>

#include <fcntl.h>
#include <unistd.h>

using namespace gnss;
using gnss::app::LogViewer;
using gnss::app::MainWindow;

class TstLogviewWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    DialectRegistry registry_ = makeBuiltinRegistry();
    link::TransportFactory transports_ = app::makeTransportFactory(gnss::sim::builtinSimulators());
    std::string scenario_;

    std::unique_ptr<QSettings> settings() {
        return std::make_unique<QSettings>(dir_.filePath("settings.ini"), QSettings::IniFormat);
    }
    std::unique_ptr<MainWindow> window(QSettings *s) {
        auto w = std::make_unique<MainWindow>(registry_, transports_, s);
        w->resize(1280, 800);
        w->show();
        return w;
    }
    // Every tab of every dock group shows its whole title (ten tabs in one group were cut to
    // "Ре…", "Поп…" in Russian at 1280x800).
    static void expectTabTitlesWhole(MainWindow &w) {
        const QString cut = test::cutTabTitle(w);
        QVERIFY2(cut.isEmpty(), qPrintable(cut));
    }
    // Everything fits a 1280x800 laptop (less a title bar and a panel): the timeline and the status
    // bar are on screen, not pushed below it.
    static void expectFitsLaptop(MainWindow &w) {
        QCoreApplication::processEvents();
        const QSize min = w.minimumSizeHint();
        QVERIFY2(min.width() <= 1280 && min.height() <= 740,
                 qPrintable(QString("%1x%2").arg(min.width()).arg(min.height())));
    }
    // Opens the scenario log and waits for its index.
    static bool openScenario(MainWindow &w, const std::string &path) {
        w.openLog(QString::fromStdString(path));
        return QTest::qWaitFor([&] { return w.logViewer()->ready(); }, 30000) &&
               !w.logViewer()->cursor()->empty();
    }
    // The docks show what the engine rebuilds at k (itself checked against a front-to-back
    // decode by tst_logview_index).
    static void expectStateAt(MainWindow &w, std::size_t k) {
        const logview::LogView *view = w.logViewer()->view();
        ReceiverState expected;
        QVERIFY(view->stateAt(k, expected));
        QCOMPARE(w.logViewer()->cursor()->current(), k);
        QVERIFY(w.stateModel()->state().epoch == expected.epoch);
        std::size_t sats = 0;
        for (const auto &row : w.satelliteModel()->rows()) sats += row.inView ? 1 : 0;
        QCOMPARE(sats, expected.epoch.satellites.size());
    }

private slots:
    void initTestCase() {
        test::Scenario sc;
        scenario_ = dir_.filePath("drive.nmea").toStdString();
        QVERIFY(test::writeFile(scenario_, test::scenarioLog(sc)));
    }

    void openingALogShowsItsDocksAndTheStateAtTheCursor() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        QVERIFY(w->findChild<QToolBar *>("timelineBar")->isVisible());
        expectFitsLaptop(*w);
        for (const char *d : {"logEventsDock", "logSummaryDock", "logChartsDock", "logTrackDock"})
            QVERIFY2(w->dock(d)->isVisibleTo(w.get()), d);
        expectTabTitlesWhole(*w);
        QCOMPARE(w->logViewer()->cursor()->epochCount(), std::size_t(600));
        expectStateAt(*w, 0);
        // The strip: fix colours everywhere, the gap and the checksum burst marked.
        auto *strip = w->findChild<ui::TimelineStrip *>("timelineStrip");
        QVERIFY(strip->width() > 600);
        bool gap = false, errors = false, event = false;
        for (const auto &b : strip->bins()) gap |= b.gap, errors |= b.errors, event |= b.event;
        QVERIFY(gap && errors && event);
        // Seek to random epochs: every dock follows, the console ends with the epoch's lines.
        std::mt19937 rng(7);
        for (int i = 0; i < 20; ++i) {
            const std::size_t k = rng() % 600;
            w->logViewer()->cursor()->seek(k, true);
            expectStateAt(*w, k);
            QVERIFY(w->logViewer()->lastPublishMs() < 1000);
        }
        // The console is the file's lines, the cursor's epoch ending at its current row.
        auto *console = w->findChild<ui::ConsoleView *>("console");
        QVERIFY(console->showingLog());
        ui::LogLinesModel *lines = w->logViewer()->lines();
        const logview::LogView *view = w->logViewer()->view();
        QTRY_COMPARE(std::uint64_t(lines->rowCount()), view->lineCount());
        QVERIFY(lines->rowCount() > 600);
        const std::size_t k = w->logViewer()->cursor()->current();
        const auto last = view->linesAround(view->epochEnd(k) - 1, 0, 1);
        QCOMPARE(lines->cursorRow(), int(view->lineAt(last[0].offset)));
        QVERIFY(lines->data(lines->index(lines->cursorRow()), Qt::DisplayRole)
                        .toString()
                        .endsWith(QString::fromLatin1(
                                view->bytes(last[0].offset, last[0].length).data(),
                                int(last[0].length))));
        // Status bar: the file and its epochs; the window's title names it.
        QTRY_VERIFY(w->findChild<QLabel *>("connectionState")->text().contains("600 epochs"));
        QVERIFY(w->windowTitle().startsWith("drive.nmea"));
        QCOMPARE(w->recentLogs().value(0),
                 QFileInfo(QString::fromStdString(scenario_)).absoluteFilePath());
        // Message statistics of the whole log arrive from the worker.
        auto *messages = w->session()->messages();
        QTRY_VERIFY(messages->rowCount() >= 3);
        // Still, once every dock has its content (a slow machine checked it only then).
        QTest::qWait(1200);
        expectFitsLaptop(*w);
    }

    // In Russian too, whose words are longer: the window still fits a 1280x800 screen.
    void theViewerFitsALaptopInRussian() {
        QTranslator russian;
        QVERIFY2(russian.load(QStringLiteral(GNSS_RU_QM)), GNSS_RU_QM);
        QCoreApplication::installTranslator(&russian);
        {
            auto s = settings();
            auto w = window(s.get());
            QVERIFY(openScenario(*w, scenario_));
            expectFitsLaptop(*w);
            QTest::qWait(1200);
            expectFitsLaptop(*w);
            QVERIFY(w->findChild<QAction *>("logPlay")->text() != QLatin1String("Play"));
            expectTabTitlesWhole(*w);
        }
        QCoreApplication::removeTranslator(&russian);
    }

    void theTransportMovesTheCursor() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        ui::LogCursor *cursor = w->logViewer()->cursor();
        auto *panel = w->findChild<ui::TimelinePanel *>("timelinePanel");
        auto act = [&](const char *name) {
            auto *a = panel->findChild<QAction *>(name);
            QVERIFY2(a && a->isEnabled(), name);
            a->trigger();
        };
        act("logStepForward");
        expectStateAt(*w, 1);
        act("logEnd");
        expectStateAt(*w, 599);
        act("logStepBack");
        expectStateAt(*w, 598);
        act("logStart");
        act("logNextEvent");
        const auto next = w->logViewer()->view()->nextEvent(0);
        QVERIFY(next);
        expectStateAt(*w, *next);
        act("logNextEvent");
        QVERIFY(cursor->current() > *next);
        act("logPrevEvent");
        QCOMPARE(cursor->current(), *next);
        // The same through the keyboard.
        cursor->seek(10);
        w->activateWindow();
        // A window shortcut answers only in the active window; activation is asynchronous.
        QVERIFY(QTest::qWaitForWindowActive(w.get()));
        QTest::keyClick(w.get(), Qt::Key_Right);
        QCOMPARE(cursor->current(), std::size_t(11));
        // A typed time: 10:05:00 is epoch 300 before the 30 s gap... the gap starts at 300, so
        // the first epoch at or after it is the one after the gap.
        QVERIFY(panel->goTo("#123"));
        expectStateAt(*w, 123);
        QVERIFY(panel->goTo("10:02:00"));
        QCOMPARE(cursor->current(), std::size_t(120));
        QVERIFY(!panel->goTo("yesterday"));
        QVERIFY(!panel->goTo("23:59:59"));
        QCOMPARE(cursor->current(), std::size_t(120));
        QVERIFY(panel->positionText().startsWith("#120 / 599"));
        // Play at 100x: the cursor runs, the docks follow; pause stops it.
        panel->setSpeed(100);
        act("logPlay");
        QVERIFY(w->logViewer()->playing());
        QTRY_VERIFY_WITH_TIMEOUT(cursor->current() > 150, 5000);
        act("logPlay");
        QVERIFY(!w->logViewer()->playing());
        const std::size_t stopped = cursor->current();
        QTest::qWait(200);
        QCOMPARE(cursor->current(), stopped);
        expectStateAt(*w, stopped);
        // As fast as possible reaches the end and stops there.
        panel->setSpeed(0);
        act("logPlay");
        QTRY_VERIFY_WITH_TIMEOUT(!w->logViewer()->playing(), 30000);
        QCOMPARE(cursor->current(), std::size_t(599));
    }

    void theStripTheEventsTheTrackAndTheChartSeek() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        ui::LogCursor *cursor = w->logViewer()->cursor();
        auto *strip = w->findChild<ui::TimelineStrip *>("timelineStrip");
        QTest::mouseClick(strip, Qt::LeftButton, {}, QPoint(strip->xOfEpoch(450), 10));
        QVERIFY(qAbs(qint64(cursor->current()) - 450) <= 1);
        expectStateAt(*w, cursor->current());
        // Shift+drag selects a range; the statistics follow it.
        QTest::mousePress(strip, Qt::LeftButton, Qt::ShiftModifier,
                          QPoint(strip->xOfEpoch(100), 10));
        QTest::mouseMove(strip, QPoint(strip->xOfEpoch(199), 10));
        QTest::mouseRelease(strip, Qt::LeftButton, Qt::ShiftModifier,
                            QPoint(strip->xOfEpoch(199), 10));
        QVERIFY(cursor->hasRange());
        const auto [a, b] = cursor->selection();
        QVERIFY(qAbs(qint64(a) - 100) <= 1 && qAbs(qint64(b) - 199) <= 1);
        auto *summary = w->findChild<ui::LogSummaryView *>("logSummaryView");
        QCOMPARE(summary->stats().first, a);
        QCOMPARE(summary->stats().last, b);
        QCOMPARE(summary->valueOf("Epochs"), QString::number(b - a + 1));
        // Epochs 100..199 are RTK float (quality 5) in the scenario.
        QVERIFY(summary->valueOf("RTK float (availability)").startsWith("100.0 %"));
        // The accuracy of the range against a typed point: what compare::Accuracy gives for
        // the range's positions, and a histogram of each of them.
        ui::AccuracyPanel *accuracy = summary->accuracy();
        accuracy->setReferenceText("55.7512,37.6184");
        std::string why;
        compare::Accuracy expected(*compare::ReferencePoint::parse("55.7512,37.6184", why));
        w->logViewer()->view()->withRecords([&, a = a, b = b](auto all) {
            for (std::size_t i = a; i <= b; ++i) {
                Epoch e;
                e.fix = all[i].fixType();
                if (all[i].hasPosition()) {
                    e.lat = all[i].lat;
                    e.lon = all[i].lon;
                }
                expected.add(e);
            }
        });
        const compare::AccuracyReport r = expected.report();
        QVERIFY(r.positions > 50);
        QTRY_COMPARE(accuracy->histogram()->count(), r.positions);
        QCOMPARE(accuracy->valueOf("CEP95"), ui::fmt::length(r.cep95, 3, ui::UnitSystem::Metric));
        QCOMPARE(accuracy->valueOf("Bias north"),
                 ui::fmt::length(r.biasNorth, 3, ui::UnitSystem::Metric));
        QVERIFY(accuracy->valueOf("Within (all)").contains("5.00 m"));
        cursor->clearRange();
        QCOMPARE(summary->valueOf("Epochs"), QString("600"));

        // An event in the list.
        auto *events = w->findChild<ui::LogEventsView *>("logEventsView");
        QTableWidget *table = events->table();
        QCOMPARE(std::size_t(table->rowCount()), w->logViewer()->view()->events().size());
        const int row = 3;
        const auto epoch = table->item(row, 0)->data(Qt::UserRole).toULongLong();
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {},
                          table->visualItemRect(table->item(row, 1)).center());
        QCOMPARE(cursor->current(), std::size_t(epoch));
        // Every description is in words, none empty.
        for (int r = 0; r < table->rowCount(); ++r) QVERIFY(!table->item(r, 2)->text().isEmpty());
        // …and says what changed, from the epoch and the one before: "RTK float → RTK fixed",
        // "station 2 (was 1)".
        const auto all = w->logViewer()->view()->events();
        int fixChanges = 0, stationChanges = 0;
        for (int r = 0; r < table->rowCount(); ++r) {
            const QString text = table->item(r, 2)->text();
            if (all[std::size_t(r)].kind == logview::EventKind::FixChange)
                fixChanges += text.contains(QStringLiteral(" → "));
            if (all[std::size_t(r)].kind == logview::EventKind::BaseStation)
                stationChanges += text.contains(QStringLiteral("(was "));
        }
        QCOMPARE(fixChanges, 5);
        QCOMPARE(stationChanges, 1); // the first station heard was none before

        // The track: a click on an epoch's dot goes there.
        w->showDock("logTrack");
        auto *track = w->findChild<ui::LogTrack *>("logTrack");
        QTRY_VERIFY(track->isVisible());
        const auto en = track->enOf(250);
        QVERIFY(en);
        const QPoint px = track->toPixel(*en).toPoint();
        QTest::mouseClick(track, Qt::LeftButton, {}, px);
        const auto near = track->epochNear(px, 12);
        QVERIFY(near);
        QCOMPARE(cursor->current(), *near);

        // The chart: a click goes to the epoch under it; the wheel zooms about the mouse.
        w->showDock("logCharts");
        auto *plot = w->findChild<ui::LogPlot *>("logPlot");
        QTRY_VERIFY(plot->isVisible());
        const int x = int(plot->xOfEpoch(520));
        QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(x, plot->plotRect().center().y()));
        QVERIFY(qAbs(qint64(cursor->current()) - 520) <= 1);
        QWheelEvent wheel(QPointF(x, 50), plot->mapToGlobal(QPointF(x, 50)), {}, QPoint(0, 120),
                          Qt::NoButton, {}, Qt::NoScrollPhase, false);
        QApplication::sendEvent(plot, &wheel);
        const auto [f0, f1] = plot->window();
        QVERIFY(f1 - f0 < 599);
        QVERIFY(f0 <= 520 && f1 >= 520);
    }

    void exportsWriteWhatTheEngineWrites() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        ui::LogCursor *cursor = w->logViewer()->cursor();
        cursor->setRange(100, 199);
        QSignalSpy done(w->logViewer(), &LogViewer::exportFinished);
        const QString gpx = dir_.filePath("range.gpx");
        QVERIFY(w->logViewer()->exportTo(LogViewer::Export::Gpx, gpx));
        QVERIFY(done.wait(20000));
        QVERIFY(done.at(0).at(0).toBool());
        QFile f(gpx);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray doc = f.readAll();
        QCOMPARE(doc.count("<trkpt "), 100);
        // NMEA: the bytes of the range exactly as in the file.
        const QString nmea = dir_.filePath("range.nmea");
        QVERIFY(w->logViewer()->exportTo(LogViewer::Export::Nmea, nmea));
        QVERIFY(done.wait(20000));
        const logview::LogView *view = w->logViewer()->view();
        const auto from = view->epoch(100)->offset, to = view->epoch(200)->offset;
        QFile n(nmea);
        QVERIFY(n.open(QIODevice::ReadOnly));
        const std::string_view expected = view->bytes(from, to - from);
        QCOMPARE(n.readAll(), QByteArray(expected.data(), qsizetype(expected.size())));
        // Statistics as JSON, and a refused name.
        const QString json = dir_.filePath("range.json");
        QVERIFY(w->logViewer()->exportTo(LogViewer::Export::StatsJson, json));
        QVERIFY(done.wait(20000));
        QFile j(json);
        QVERIFY(j.open(QIODevice::ReadOnly));
        QVERIFY(j.readAll().contains("\"epochs\":100"));
        QVERIFY(!LogViewer::formatOfSuffix("docx"));
        QString why;
        QVERIFY(!w->logViewer()->exportTo(LogViewer::Export::Gpx,
                                          dir_.filePath("no/such/folder/x.gpx"), &why) ||
                (done.wait(20000) && !done.last().at(0).toBool()));
    }

    // A small log is indexed before open() returns (the worker outruns it), and Export and Play
    // Out are still offered: they were once greyed after a race with the open itself. Opened
    // many times, so the fast case is met whichever way the threads run here.
    void aLogIndexedAtOnceCanBeExportedAndPlayedOut() {
        test::Scenario sc;
        const std::string all = test::scenarioLog(sc);
        const QString path = dir_.filePath("small.nmea");
        QVERIFY(test::writeFile(path.toStdString(), all.substr(0, all.find("$GPRMC,100003.00"))));
        auto s = settings();
        auto w = window(s.get());
        auto *exportAction = w->findChild<QAction *>("exportLogAction");
        auto *playOut = w->findChild<QAction *>("playOutAction");
        for (int k = 0; k < 30; ++k) {
            QVERIFY(openScenario(*w, path.toStdString()));
            QVERIFY2(exportAction->isEnabled(), qPrintable(QString("open %1").arg(k)));
            QVERIFY2(playOut->isEnabled(), qPrintable(QString("open %1").arg(k)));
        }
    }

    // Play Out: the range's bytes, exactly, to a TCP client and to a pseudo-terminal's reader;
    // a malformed request is refused before anything is opened.
    void playOutSendsTheRangeAsInTheFile() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        w->logViewer()->cursor()->setRange(100, 199);
        const logview::LogView *view = w->logViewer()->view();
        const auto from = view->epoch(100)->offset, to = view->epoch(200)->offset;
        const std::string_view expectedView = view->bytes(from, to - from);
        const QByteArray expected(expectedView.data(), qsizetype(expectedView.size()));
        app::LogPlayer *player = w->logPlayer();
        QSignalSpy finished(player, &app::LogPlayer::finished);

        app::LogPlayer::Target tcp;
        tcp.kind = app::LogPlayer::Target::Kind::Tcp;
        {
            QTcpServer probe; // a free port
            QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
            tcp.tcpPort = probe.serverPort();
        }
        QString why;
        QVERIFY2(player->start(w->logViewer()->shared(), 100, 199, 1000, false, tcp, &why),
                 qPrintable(why));
        QVERIFY(player->statusText().contains("waiting for a client"));
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, tcp.tcpPort);
        QVERIFY(client.waitForConnected(5000));
        QByteArray got;
        QTRY_VERIFY_WITH_TIMEOUT((got += client.readAll(), got.size() >= expected.size()) ||
                                         (finished.size() > 0 && client.bytesAvailable() == 0 &&
                                          got.size() >= expected.size()),
                                 10000);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 5000);
        got += client.readAll();
        QCOMPARE(got, expected);

        app::LogPlayer::Target pty; // the default: a new pseudo-terminal
        QVERIFY2(player->start(w->logViewer()->shared(), 100, 199, 200, false, pty, &why),
                 qPrintable(why));
        const QString device = player->ptyPath();
        QVERIFY(device.startsWith("/dev/pts/"));
        const int fd = test::openRawPty(QFile::encodeName(device).constData(), O_NONBLOCK);
        QVERIFY(fd >= 0);
        QByteArray viaPty;
        QTRY_VERIFY_WITH_TIMEOUT(([&] {
                                     char buf[4096];
                                     for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;)
                                         viaPty.append(buf, n);
                                     return viaPty.size() >= expected.size();
                                 })(),
                                 10000);
        ::close(fd);
        QCOMPARE(viaPty, expected);
        QTRY_VERIFY(!player->running());
        QVERIFY(player->statusText().contains("finished"));
        QCOMPARE(player->bytesDropped(), quint64(0));

        app::LogPlayer::Target serial;
        serial.kind = app::LogPlayer::Target::Kind::Serial;
        QVERIFY(!player->start(w->logViewer()->shared(), 0, 10, 1, false, serial, &why));
        QVERIFY(why.contains("serial port"));
        QVERIFY(!player->start(w->logViewer()->shared(), 0, 10, 0, false, pty, &why));
        QVERIFY(why.contains("speed"));
        QVERIFY(!player->running());
        // The dialog is there, with the range.
        auto *playOut = w->findChild<QAction *>("playOutAction");
        QVERIFY2(playOut->isEnabled(), "Play Out is offered once the log is indexed");
        playOut->trigger();
        auto *dialog = w->findChild<app::PlayOutDialog *>();
        QVERIFY2(dialog, "File > Play Out opens its dialog");
        QTRY_VERIFY(dialog->isVisible());
    }

    // A logger still writing: with Follow on, the timeline grows and the cursor stays at the end.
    void aGrowingLogIsFollowed() {
        test::Scenario sc;
        const std::string all = test::scenarioLog(sc);
        const std::string half = all.substr(0, all.find("$GPRMC,100140.00")); // 100 epochs
        const QString path = dir_.filePath("growing.nmea");
        QVERIFY(test::writeFile(path.toStdString(), half));
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, path.toStdString()));
        ui::LogCursor *cursor = w->logViewer()->cursor();
        const std::size_t before = cursor->epochCount();
        QVERIFY(before >= 99 && before <= 100);
        cursor->seek(before - 1);
        // The console filtered to RMC: the filter goes on over what the file gains.
        ui::LogLinesModel *lines = w->logViewer()->lines();
        w->findChild<QLineEdit *>("consoleFilter")->setText("RMC");
        QTRY_VERIFY(!lines->filtering() && lines->rowCount() >= 99);
        const int rmcBefore = lines->rowCount();
        w->findChild<QCheckBox *>("logFollow")->setChecked(true);
        QVERIFY(w->logViewer()->following());
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::Append));
            f.write(QByteArray::fromStdString(
                    all.substr(half.size(), all.find("$GPRMC,100220.00") - half.size())));
        }
        QTRY_VERIFY_WITH_TIMEOUT(cursor->epochCount() >= 139, 5000);
        QCOMPARE(cursor->current(), cursor->epochCount() - 1);
        expectStateAt(*w, cursor->current());
        QVERIFY(w->findChild<QLabel *>("connectionState")->text().contains("following"));
        QTRY_VERIFY(lines->rowCount() >= rmcBefore + 39);
        QCOMPARE(w->logViewer()->view()->epochAtOffset(*lines->offsetOfRow(lines->cursorRow())),
                 std::optional<std::size_t>(cursor->current()));
    }

    // The console while a log is open: every line of the file (a virtual list over the mapping),
    // the cursor's epoch marked and in view, a filter over the whole log, a double click on a
    // line moves the cursor to its moment, and closing the log gives the live console back.
    void theConsoleIsTheWholeFileAtTheCursor() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        auto *console = w->findChild<ui::ConsoleView *>("console");
        auto *list = console->findChild<QListView *>("consoleLines");
        ui::LogLinesModel *lines = w->logViewer()->lines();
        const logview::LogView *view = w->logViewer()->view();
        QVERIFY(list->model() == lines);
        QTRY_VERIFY(lines->rowCount() > 0);
        QCOMPARE(console->visibleLines(), lines->rowCount());
        QVERIFY(!console->findChild<QToolButton *>("consolePause")->isVisibleTo(console));
        // Nothing takes commands: no send box.
        QVERIFY(!console->findChild<QLineEdit *>("consoleInput")->isVisibleTo(console));
        // Every line of the file, in order: the first and the last.
        const std::string text = test::readFile(scenario_);
        const auto first = lines->data(lines->index(0), Qt::DisplayRole).toString();
        std::string firstLine = text.substr(0, text.find('\n'));
        if (!firstLine.empty() && firstLine.back() == '\r') firstLine.pop_back();
        QVERIFY2(first.endsWith(QString::fromLatin1(firstLine)), qPrintable(first));
        // Seeks: the cursor's last line is the current row, in the viewport, marked.
        ui::LogCursor *cursor = w->logViewer()->cursor();
        for (std::size_t k : {std::size_t(300), std::size_t(10), std::size_t(599)}) {
            cursor->seek(k, true);
            const int row = lines->cursorRow();
            QVERIFY(row >= 0);
            QCOMPARE(list->currentIndex().row(), row);
            QVERIFY(list->viewport()->rect().intersects(list->visualRect(list->currentIndex())));
            QVERIFY(lines->data(lines->index(row), Qt::BackgroundRole).isValid());
            const auto offset = lines->offsetOfRow(row);
            QVERIFY(offset);
            QCOMPARE(view->epochAtOffset(*offset), std::optional<std::size_t>(k));
            if (row > 50)
                QVERIFY(!lines->data(lines->index(row - 50), Qt::BackgroundRole).isValid());
        }
        // A double click on a line far from the cursor: the cursor goes to the epoch holding it.
        const int far = lines->rowCount() / 2;
        emit list->activated(lines->index(far));
        const auto farEpoch = view->epochAtOffset(*lines->offsetOfRow(far));
        QCOMPARE(cursor->current(), *farEpoch);
        // The filter runs over the whole log: only GGA lines, each of them.
        auto *filter = console->findChild<QLineEdit *>("consoleFilter");
        filter->setText("GGA");
        std::size_t gga = 0; // lines that start a sentence whose address has GGA
        for (std::size_t at = 0; at < text.size();) {
            const std::size_t end = std::min(text.find('\n', at), text.size());
            const std::string line = text.substr(at, end - at);
            const std::size_t addressEnd = line.find_first_of(",*");
            if (!line.empty() && (line[0] == '$' || line[0] == '!') &&
                line.substr(0, addressEnd).find("GGA") != std::string::npos)
                ++gga;
            at = end + 1;
        }
        QTRY_COMPARE(std::size_t(lines->rowCount()), gga);
        auto *note = console->findChild<QLabel *>("consoleNote");
        QTRY_VERIFY(note->isVisibleTo(console) && note->text().contains(QString::number(gga)));
        for (int r = 0; r < lines->rowCount(); r += 37)
            QVERIFY(lines->data(lines->index(r), ui::ConsoleModel::AddressRole)
                            .toString()
                            .endsWith("GGA"));
        cursor->seek(200, true);
        QVERIFY(lines->cursorRow() >= 0);
        QCOMPARE(view->epochAtOffset(*lines->offsetOfRow(lines->cursorRow())),
                 std::optional<std::size_t>(200));
        // A filter that is no expression says so and shows nothing.
        filter->setText("GGA(");
        QCOMPARE(lines->rowCount(), 0);
        QVERIFY(note->text().contains("not a valid"));
        filter->clear();
        QTRY_COMPARE(std::uint64_t(lines->rowCount()), view->lineCount());
        // Closing the log: the live console again (the selected receiver's), with its pause
        // button.
        w->closeLog();
        console = qobject_cast<ui::ConsoleView *>(w->dock("consoleDock")->widget());
        QVERIFY(console);
        list = console->findChild<QListView *>("consoleLines");
        QVERIFY(!console->showingLog());
        QVERIFY(list->model() != lines);
        QVERIFY(console->findChild<QToolButton *>("consolePause")->isVisibleTo(console));
        QVERIFY(console->findChild<QLineEdit *>("consoleInput")->isVisibleTo(console));
    }

    // A log of more lines than the console's window: the rows are the lines around the cursor,
    // moved with it to either end of the log, each still the file's line.
    void theConsoleWindowFollowsTheCursorThroughABigLog() {
        const std::string path = dir_.filePath("big-console.nmea").toStdString();
        std::string text;
        bench::generateLog(text, 4'000'000);
        QVERIFY(test::writeFile(path, text));
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, path));
        ui::LogLinesModel *lines = w->logViewer()->lines();
        const logview::LogView *view = w->logViewer()->view();
        QTRY_VERIFY(view->lineCount() > 2 * ui::LogLinesModel::kWindow &&
                    lines->rowCount() == int(ui::LogLinesModel::kWindow));
        auto *list = w->findChild<QListView *>("consoleLines");
        ui::LogCursor *cursor = w->logViewer()->cursor();
        const std::size_t last = cursor->epochCount() - 1;
        for (std::size_t k : {last, std::size_t(0), last / 2, last - 3, std::size_t(5)}) {
            cursor->seek(k, true);
            const int row = lines->cursorRow();
            QVERIFY2(row >= 0, qPrintable(QString::number(k)));
            QCOMPARE(lines->rowCount(), int(ui::LogLinesModel::kWindow));
            QCOMPARE(view->epochAtOffset(*lines->offsetOfRow(row)), std::optional<std::size_t>(k));
            QCOMPARE(list->currentIndex().row(), row);
            QVERIFY(list->viewport()->rect().intersects(list->visualRect(list->currentIndex())));
            // The row is the file's line: its text ends the row's display.
            const auto ref = view->line(view->lineAt(*lines->offsetOfRow(row)));
            QVERIFY(lines->data(lines->index(row), Qt::DisplayRole)
                            .toString()
                            .endsWith(QString::fromLatin1(
                                    view->bytes(ref->offset, ref->length).data(),
                                    int(ref->length))));
        }
        QVERIFY(lines->note().contains(QString::number(view->lineCount()).right(3)));
    }

    // A followed log that gains 50 MB at once: the growth is indexed on a worker while the GUI
    // thread keeps turning. The engine's hook holds the follow in the middle of its decoding
    // until the GUI thread has ticked (a 10 ms timer) five times, reading the log and repainting
    // the strip each time: had the GUI thread been inside the follow, or waiting on a lock held
    // over it, no tick would come and the hook would give up after 60 s.
    void aBigGrowthIsIndexedOffTheGuiThread() {
        std::string log;
        bench::generateLog(log, std::size_t(51) << 20);
        const std::size_t cut = log.find('\n', std::size_t(1) << 20) + 1;
        const QString path = dir_.filePath("logger.nmea");
        QVERIFY(test::writeFile(path.toStdString(), std::string_view(log).substr(0, cut)));
        std::atomic<bool> inside{false}, sawTicks{false};
        std::atomic<int> ticksInside{0};
        logview::LogViewOptions o;
        o.whileFollowing = [&] {
            inside = true;
            QDeadlineTimer until(60000);
            while (ticksInside.load() < 5 && !until.hasExpired())
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            sawTicks = ticksInside.load() >= 5;
            inside = false;
        };
        auto s = settings();
        auto w = window(s.get());
        w->logViewer()->setViewOptions(o);
        QVERIFY(openScenario(*w, path.toStdString()));
        ui::LogCursor *cursor = w->logViewer()->cursor();
        const std::size_t before = cursor->epochCount();
        QVERIFY(before > 100);
        cursor->seek(before - 1);
        auto *strip = w->findChild<ui::TimelineStrip *>("timelineStrip");
        int ticks = 0;
        bool grewEarly = false, readsFailed = false;
        QTimer timer;
        timer.setInterval(10);
        connect(&timer, &QTimer::timeout, this, [&] {
            ++ticks;
            if (!inside) return;
            // The views read the log as they do on every frame.
            const logview::LogView *view = w->logViewer()->view();
            ReceiverState st;
            grewEarly |= view->epochCount() != before;
            readsFailed |= !view->stateAt(before - 1, st);
            strip->repaint();
            ++ticksInside;
        });
        timer.start();
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::Append));
            QCOMPARE(f.write(log.data() + cut, qint64(log.size() - cut)), qint64(log.size() - cut));
        }
        w->findChild<QCheckBox *>("logFollow")->setChecked(true);
        QTRY_VERIFY_WITH_TIMEOUT(w->logViewer()->followBusy(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(cursor->epochCount() > before * 20, 120000);
        QTRY_VERIFY_WITH_TIMEOUT(!w->logViewer()->followBusy(), 20000);
        timer.stop();
        QVERIFY(sawTicks);
        QVERIFY(ticksInside >= 5);
        QVERIFY(!grewEarly && !readsFailed);
        qInfo("%d ticks, %d while the follow decoded %zu new epochs", ticks, ticksInside.load(),
              cursor->epochCount() - before);
        // The whole growth is there, as indexing the file at once gives, and the cursor is at
        // its end with the docks showing it.
        logview::LogView whole(registry_);
        QVERIFY(test::openAndWait(whole, path.toStdString()));
        QCOMPARE(cursor->epochCount(), whole.epochCount());
        QCOMPARE(cursor->current(), cursor->epochCount() - 1);
        expectStateAt(*w, cursor->current());
        QVERIFY(w->findChild<QLabel *>("connectionState")->text().contains("following"));
    }

    // A .gz log: its first epoch is on screen while it is still being unpacked (the worker held
    // there by the test's hook: until it goes on, the log is unpacking), then it is indexed.
    void aGzipLogShowsItsFirstEpochWhileUnpacking() {
        std::string log;
        bench::generateLog(log, std::size_t(16) << 20);
        const QString path = dir_.filePath("drive.nmea.gz");
        gzFile gz = gzopen(path.toLocal8Bit().constData(), "wb1");
        QVERIFY(gz);
        QCOMPARE(gzwrite(gz, log.data(), unsigned(log.size())), int(log.size()));
        QCOMPARE(gzclose(gz), Z_OK);
        std::atomic<bool> held{false}, released{false};
        logview::LogViewOptions o;
        o.onFirstEpoch = [&] {
            held = true;
            QDeadlineTimer until(60000);
            while (!released && !until.hasExpired())
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        };
        auto s = settings();
        auto w = window(s.get());
        w->logViewer()->setViewOptions(o);
        w->openLog(path);
        QTRY_VERIFY_WITH_TIMEOUT(held.load(), 20000);
        const auto first = w->logViewer()->view()->firstEpoch();
        QVERIFY(first && first->hasPosition());
        QTRY_COMPARE_WITH_TIMEOUT(w->stateModel()->state().epoch.lat, first->lat, 20000);
        QCOMPARE(w->stateModel()->state().epoch.lon, first->lon);
        auto *status = w->findChild<QLabel *>("connectionState");
        QVERIFY2(status->text().startsWith("Log drive.nmea.gz: unpacking"),
                 qPrintable(status->text()));
        QCOMPARE(w->logViewer()->view()->progress().phase, logview::LogView::Phase::Inflating);
        released = true;
        QTRY_VERIFY_WITH_TIMEOUT(w->logViewer()->ready(), 60000);
        QVERIFY(w->logViewer()->cursor()->epochCount() > 1000);
        expectStateAt(*w, 0);
    }

    // A big log being indexed can be cancelled from the timeline (its button, or Esc there): the
    // status bar and the strip say so, what was indexed from the start stays on screen, and the
    // window goes on working (another log opens). Cancelled at once, little or nothing is kept;
    // cancelled with the worker held at the first epoch (the test's hook), its first 4 MB are.
    void indexingCanBeCancelled_data() {
        QTest::addColumn<bool>("byKey");
        QTest::addColumn<bool>("afterFirstEpoch");
        QTest::newRow("the Cancel button, at once") << false << false;
        QTest::newRow("Esc in the timeline, at once") << true << false;
        QTest::newRow("the Cancel button, after the first epoch") << false << true;
    }
    void indexingCanBeCancelled() {
        QFETCH(bool, byKey);
        QFETCH(bool, afterFirstEpoch);
        const QString path = dir_.filePath("big.nmea");
        if (!QFile::exists(path)) {
            std::string log;
            bench::generateLog(log, std::size_t(128) << 20);
            QVERIFY(test::writeFile(path.toStdString(), log));
        }
        std::atomic<bool> held{false}, clicked{false};
        logview::LogViewOptions o;
        if (afterFirstEpoch)
            o.onFirstEpoch = [&] {
                held = true;
                QDeadlineTimer until(60000);
                while (!clicked && !until.hasExpired())
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
            };
        auto s = settings();
        auto w = window(s.get());
        w->logViewer()->setViewOptions(o);
        auto *panel = w->findChild<ui::TimelinePanel *>("timelinePanel");
        auto *button = panel->findChild<QToolButton *>("logCancelButton");
        QVERIFY(button && !button->isVisible());
        w->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w.get()));
        w->openLog(path);
        // Cancelled at once (the 128 MB take far longer to index than this), or once held.
        QCOMPARE(w->logViewer()->indexing(), true);
        QVERIFY(button->isVisible());
        QVERIFY(panel->cancelAction()->isEnabled());
        if (afterFirstEpoch) QTRY_VERIFY_WITH_TIMEOUT(held.load(), 20000);
        if (byKey) {
            auto *strip = panel->strip();
            strip->setFocus();
            QVERIFY(strip->hasFocus());
            QTest::keyClick(strip, Qt::Key_Escape);
        } else {
            QTest::mouseClick(button, Qt::LeftButton);
        }
        clicked = true;
        QTRY_COMPARE_WITH_TIMEOUT(w->logViewer()->view()->progress().phase,
                                  logview::LogView::Phase::Cancelled, 20000);
        auto *status = w->findChild<QLabel *>("connectionState");
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains("indexing cancelled"), 20000);
        QVERIFY2(status->text().startsWith("Log big.nmea: "), qPrintable(status->text()));
        QVERIFY(!w->logViewer()->indexing() && !w->logViewer()->failed());
        // The status bar reads the phase whenever it is redrawn; the button goes with the
        // viewer's next poll (a tick later under a sanitizer's load).
        QTRY_VERIFY_WITH_TIMEOUT(!button->isVisible(), 5000);
        QVERIFY(!panel->cancelAction()->isEnabled());
        ui::LogCursor *cursor = w->logViewer()->cursor();
        const std::size_t kept = w->logViewer()->view()->epochCount();
        if (afterFirstEpoch) QVERIFY(kept > 100);
        if (kept == 0) {
            QVERIFY(cursor->empty());
            QVERIFY(!w->findChild<QAction *>("logStepForward")->isEnabled());
            QVERIFY(!w->findChild<QAction *>("exportLogAction")->isEnabled());
        } else {
            // What was indexed is a log of its own: shown, seekable, exportable.
            QTRY_VERIFY(w->logViewer()->ready());
            QVERIFY2(status->text().contains(QString("the first %1 epochs").arg(kept)),
                     qPrintable(status->text()));
            QCOMPARE(cursor->epochCount(), kept);
            QVERIFY(w->findChild<QAction *>("exportLogAction")->isEnabled());
            expectStateAt(*w, 0);
            cursor->seek(kept / 2, true);
            expectStateAt(*w, kept / 2);
        }
        qInfo("%zu epochs kept", kept);
        // Esc again does nothing; the window goes on: another log opens and the docks follow.
        QTest::keyClick(panel->strip(), Qt::Key_Escape);
        QVERIFY(openScenario(*w, scenario_));
        QVERIFY(!button->isVisible());
        QVERIFY(status->text().contains("600 epochs"));
        expectStateAt(*w, 0);
        w->logViewer()->cursor()->seek(300, true);
        expectStateAt(*w, 300);
    }

    void badFilesSaySoAndNothingBreaks_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("word");
        QTest::newRow("empty") << QByteArray() << "";
        QByteArray noise(100000, '\0');
        std::mt19937 rng(3);
        for (auto &c : noise) c = char(rng() % 256);
        QTest::newRow("random bytes") << noise << "no NMEA found";
        QTest::newRow("a text file")
                << QByteArray("Dear user,\nthis is no log.\n") << "no NMEA found";
        QByteArray longLine = "$GPGGA," + QByteArray(4096, '1') + "*00\r\n";
        QTest::newRow("4096-byte line") << longLine << "";
    }
    void badFilesSaySoAndNothingBreaks() {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, word);
        const QString path = dir_.filePath("bad.nmea");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(bytes);
        }
        auto s = settings();
        auto w = window(s.get());
        w->openLog(path);
        QTRY_VERIFY_WITH_TIMEOUT(
                w->logViewer()->view()->progress().phase != logview::LogView::Phase::Indexing &&
                        w->logViewer()->view()->progress().phase != logview::LogView::Phase::Idle,
                20000);
        QTest::qWait(200);
        const QString status = w->findChild<QLabel *>("connectionState")->text();
        QVERIFY2(status.startsWith("Log bad.nmea: "), qPrintable(status));
        if (!word.isEmpty()) QVERIFY2(status.contains(word), qPrintable(status));
        QVERIFY(w->logViewer()->cursor()->empty());
        // The transport is off; a key does nothing.
        QTest::keyClick(w.get(), Qt::Key_Right);
        QVERIFY(!w->findChild<QAction *>("logStepForward")->isEnabled());
        // A missing file too.
        w->openLog(dir_.filePath("missing.nmea"));
        QTRY_VERIFY(w->logViewer()->failed());
        QVERIFY(w->findChild<QLabel *>("connectionState")->text().startsWith("Log missing.nmea: "));
    }

    // A time or epoch the log does not hold is refused by the Go to box with the log's first
    // and last epoch, and a --at outside the log leaves the cursor at #0 and says why there.
    void aTimeOutsideTheLogIsRefusedByTheGoToBox() {
        auto s = settings();
        auto w = window(s.get());
        w->openLog(QString::fromStdString(scenario_), "#3000");
        QTRY_VERIFY(w->logViewer()->ready());
        auto *message = w->findChild<QLabel *>("logMessage");
        QVERIFY(message);
        const QString span = "2024-03-15T10:00:00.000Z (#0) to 2024-03-15T09:10:29.000Z (#599)";
        QTRY_COMPARE(message->text(), "#3000 is after the log's end: it runs from " + span);
        QCOMPARE(w->logViewer()->cursor()->current(), std::size_t(0));
        auto *panel = w->findChild<ui::TimelinePanel *>();
        QVERIFY(panel);
        QVERIFY(!panel->goTo("#600"));
        QCOMPARE(message->text(), "#600 is after the log's end: it runs from " + span);
        QVERIFY(!panel->goTo("2024-03-14T12:00:00Z"));
        QCOMPARE(message->text(),
                 "2024-03-14T12:00:00Z is before the log's start: it runs from " + span);
        QCOMPARE(w->logViewer()->cursor()->current(), std::size_t(0));
        // The receiver reset at #400 took the time back an hour: 09:07:00 is after it, not #0.
        QVERIFY(panel->goTo("09:07:00"));
        QVERIFY(message->text().isEmpty());
        const auto at = w->logViewer()->view()->epoch(w->logViewer()->cursor()->current());
        QVERIFY(at);
        QCOMPARE(QString::fromStdString(logview::formatTime(*at)),
                 QString("2024-03-15T09:07:00.000Z"));
    }

    void aLiveSourceClosesTheLogAndTheCommandLineOpensOne() {
        auto s = settings();
        auto w = window(s.get());
        QVERIFY(openScenario(*w, scenario_));
        w->connectAtStart(link::SourceSpec{link::SourceSpec::Kind::Simulator, "nmea"});
        QTRY_VERIFY(!w->logViewer()->isOpen());
        QVERIFY(!w->findChild<QToolBar *>("timelineBar")->isVisible());
        QString error;
        const QStringList simulated{"nvs"};
        const QString log = QString::fromStdString(scenario_);
        auto o = app::parseStartupOptions({"gnss-workbench", log}, simulated, error);
        QVERIFY(o);
        QCOMPARE(o->open, log);
        o = app::parseStartupOptions({"gnss-workbench", "--open", log}, simulated, error);
        QVERIFY(o);
        QCOMPARE(o->open, log);
        o = app::parseStartupOptions({"gnss-workbench", log, "--at", "10:02:00"}, simulated, error);
        QVERIFY(o);
        QCOMPARE(o->at, QString("10:02:00"));
        QVERIFY(!app::parseStartupOptions({"gnss-workbench", log, "--at", "soon"}, simulated,
                                          error));
        QVERIFY(!app::parseStartupOptions({"gnss-workbench", "--at", "#5"}, simulated, error));
        w->openLog(log, "10:02:00");
        QTRY_VERIFY(w->logViewer()->ready());
        QCOMPARE(w->logViewer()->cursor()->current(), std::size_t(120));
        expectStateAt(*w, 120);
        // A log that is not there is a failure to open (exit 1), not a malformed command line.
        o = app::parseStartupOptions({"gnss-workbench", "x.nmea"}, simulated, error);
        QVERIFY(o);
        QCOMPARE(app::missingLog(*o), QString("No such log: x.nmea"));
        QVERIFY(app::missingLog(app::StartupOptions{}).isEmpty());
        QVERIFY(!app::parseStartupOptions({"gnss-workbench", "a.nmea", "b.nmea"}, simulated,
                                          error));
        QVERIFY(!app::parseStartupOptions({"gnss-workbench", log, "--sim", "nvs"}, simulated,
                                          error));
    }
};

QTEST_MAIN(TstLogviewWindow)
#include "tst_logview_window.moc"
