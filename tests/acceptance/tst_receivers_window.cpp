// Several receivers in the real window at 1280x800: an NV08C-RTK at 38400 baud and a GeoS-5 at
// 57600, simulated on pseudo-terminals, both found with baud "auto" through the real QSerialPort.
// The GeoS-5 is told to differ (0.3 m east, -0.2 m north, 0.5 m up; GPS -3 dB, GLONASS +2 dB;
// G05 and R12 dropped) and both report the truth of one sky (--noise 0, --start now): the
// Compare dock shows what it was told (position within 5 cm, C/N0 within 1 dB), and so does
// gnss-cli compare on the same pair. Docks follow the selected receiver or stay pinned; one
// receiver unplugged leaves the other's epochs flowing and its recording byte-exact; one that hangs
// and one that floods junk leave a healthy one untouched, all three command queues at work.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "cli_run.h"
#include "common/app_transports.h"
#include "compare_json.h"
#include "config/settings_engine.h"
#include "corrections/correction_forwarder.h"
#include "gui/connection_bar.h"
#include "gui/corrections_controller.h"
#include "gui/main_window.h"
#include "gui/receivers_strip.h"
#include "link/connection.h"
#include "link/recording.h"
#include "models/compare_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "session/receiver_link.h"
#include "settings/setting_editors.h"
#include "settings/settings_view.h"
#include "sim/rtcm_base_station.h"
#include "sim_process.h"
#include "views/compare_view.h"
#include "views/console_view.h"
#include "views/fix_view.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QInputDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabBar>
#include <QTableWidget>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QWheelEvent>

#include <cmath>

using namespace gnss;
using gnss::link::SourceSpec;
using gnss::link::test::SimProcess;
using gnss::session::ReceiverLink;

namespace {

const QStringList kTold = {"--offset",         "0.3,-0.2,0.5", "--cn0-offset",
                           "GPS:-3,GLONASS:2", "--drop",       "G05,R12"};

double constellationCn0(const compare::PairReport &p, Constellation c) {
    for (const auto &x : p.perConstellation)
        if (x.system == c) return x.difference.mean;
    return NAN;
}

// The summary table's value in the row named `row`, column of receiver `receiver`.
QString summaryCell(QTableWidget *t, const QString &row, int receiver) {
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0) && t->item(r, 0)->text() == row)
            return t->item(r, receiver + 1) ? t->item(r, receiver + 1)->text() : QString();
    return {};
}

bool connected(ui::ReceiverSession *s) {
    return s->link()->state() == ReceiverLink::State::Connected && s->state()->epochCount() > 0;
}

// The window at laptop size, its connection bar and source list, `spec` chosen.
std::pair<app::ConnectionBar *, QComboBox *> sourceBar(app::MainWindow &w, const SourceSpec &spec) {
    w.resize(1280, 800);
    w.show();
    auto *bar = w.findChild<app::ConnectionBar *>();
    bar->select(spec);
    return {bar, w.findChild<QComboBox *>("sourceCombo")};
}

} // namespace

class TstReceiversWindow : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();
    link::TransportFactory transports_ = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QTemporaryDir dir_;

private slots:
    void anNv08cAndAGeoS5SideBySide() {
        SimProcess nvs({"--dialect", "nvs", "--baud", "38400", "--start", "now", "--noise", "0"});
        SimProcess geos(QStringList{"--dialect", "geostar", "--baud", "57600", "--start", "now",
                                    "--noise", "0"} +
                        kTold);
        REQUIRE_SIM(nvs);
        REQUIRE_SIM(geos);
        QSettings settings(dir_.filePath("window.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.showDock("compare");
        // The first as --port A would (baud "auto"); the second as a user adds it: a port the
        // system does not list (a pseudo-terminal), typed as a path, then Add receiver.
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, nvs.device, 0}});
        auto *bar = w.findChild<app::ConnectionBar *>();
        auto *source = w.findChild<QComboBox *>("sourceCombo");
        QTimer::singleShot(0, this, [&] {
            QWidget *modal = QApplication::activeModalWidget();
            if (auto *d = qobject_cast<QInputDialog *>(modal)) {
                d->setTextValue(geos.device);
                d->accept();
            } else if (modal) {
                modal->close(); // not the dialog expected: the comparison below fails
            }
        });
        source->setCurrentIndex(source->findData("port?")); // as a click on it does
        emit source->activated(source->currentIndex());
        QCOMPARE(bar->selection().toString(),
                 (SourceSpec{SourceSpec::Kind::Serial, geos.device, 0}.toString()));
        w.findChild<QPushButton *>("addReceiverButton")->click();
        QCOMPARE(w.sessions().size(), 2);
        ui::ReceiverSession *a = w.sessions()[0], *b = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b), 40000);
        QCOMPARE(a->link()->detectedBaud(), 38400);
        QCOMPARE(b->link()->detectedBaud(), 57600);
        // Named by model and port; the strip shows both.
        QTRY_VERIFY_WITH_TIMEOUT(a->name().startsWith("NV08C") && a->name().endsWith(nvs.device),
                                 15000);
        QTRY_VERIFY_WITH_TIMEOUT(b->name().startsWith("GeoS") && b->name().endsWith(geos.device),
                                 15000);
        auto *strip = w.findChild<app::ReceiversStrip *>();
        QTRY_VERIFY(strip->isVisible() && strip->chips().size() == 2);
        QTRY_VERIFY(strip->chips()[1]->name().contains(b->name()));
        QVERIFY(a->colour() != b->colour());
        w.selectReceiver(a);

        // The GeoS-5's port asked for again, as a third receiver: refused before it is opened,
        // with the receiver that has it selected and named.
        bar->select({SourceSpec::Kind::Serial, geos.device, 0});
        w.findChild<QPushButton *>("addReceiverButton")->click();
        QCOMPARE(w.sessions().size(), 2);
        QCOMPARE(w.selectedSession(), b);
        const QString said = w.statusBar()->currentMessage();
        QVERIFY2(said.contains(geos.device + " is receiver 2 already") && said.contains(b->name()),
                 qPrintable(said));
        QVERIFY(connected(b));
        w.selectReceiver(a);

        // The Compare dock: what the GeoS-5 was told, within 5 cm and 1 dB.
        ui::CompareModel *cmp = w.comparison();
        QTRY_VERIFY_WITH_TIMEOUT(cmp->matches().size() >= 8, 30000);
        QTest::qWait(600); // the dock's next refresh
        const compare::PairReport p = cmp->report().pairs.at(0);
        QVERIFY2(std::abs(p.east.mean - 0.3) < 0.05, qPrintable(QString::number(p.east.mean)));
        QVERIFY2(std::abs(p.north.mean + 0.2) < 0.05, qPrintable(QString::number(p.north.mean)));
        QVERIFY2(std::abs(p.up.mean - 0.5) < 0.05, qPrintable(QString::number(p.up.mean)));
        const double gps = constellationCn0(p, Constellation::Gps),
                     glonass = constellationCn0(p, Constellation::Glonass);
        QVERIFY2(std::abs(gps + 3) < 1, qPrintable(QString::number(gps)));
        QVERIFY2(std::abs(glonass - 2) < 1, qPrintable(QString::number(glonass)));
        auto *view = w.dock("compareDock")->findChild<ui::CompareView *>();
        QVERIFY(view);
        view->refresh();
        const double shownEast = summaryCell(view->summary(), "East mean (m)", 1).toDouble();
        QVERIFY2(std::abs(shownEast - 0.3) < 0.05,
                 qPrintable(summaryCell(view->summary(), "East mean (m)", 1)));
        // The dropped satellites the reference tracks now (which are up depends on the time of
        // day) are listed as only in it.
        const QString only = summaryCell(view->summary(), "Only in the reference", 1);
        const compare::Observation *reference = cmp->latest(0);
        QVERIFY(reference);
        for (const SatelliteRef dropped :
             {SatelliteRef{Constellation::Gps, 5}, SatelliteRef{Constellation::Glonass, 12}})
            for (const compare::SignalLevel &l : reference->levels)
                if (l.sat == dropped)
                    QVERIFY2(only.contains(QString::fromStdString(satelliteLabel(dropped))),
                             qPrintable(only));

        // Docks follow the selection (Ctrl+2), or stay with the receiver they are pinned to.
        QDockWidget *fix = w.dock("fixDock");
        QDockWidget *rover = w.duplicateDock("fix", b);
        QVERIFY(rover);
        QCOMPARE(w.pinnedSession(rover), b);
        QVERIFY2(rover->windowTitle().contains("#2"), qPrintable(rover->windowTitle()));
        QAction *second = w.findChild<QAction *>("selectReceiver2");
        QVERIFY(second);
        QCOMPARE(second->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_2));
        w.pinDock(fix, a);
        second->trigger();
        QCOMPARE(w.selectedSession(), b);
        QCOMPARE(w.dockSession(fix), a);
        QCOMPARE(w.dockSession(w.dock("skyDock")), b);
        QVERIFY(w.dock("settingsDock")->windowTitle().contains("#2"));
        w.findChild<QAction *>("selectReceiver1")->trigger();
        QCOMPARE(w.dockSession(w.dock("skyDock")), a);

        // gnss-cli compare on the same pair (the window lets go of the ports first).
        const std::size_t windowMatches = cmp->matches().size();
        a->link()->disconnectFromSource();
        b->link()->disconnectFromSource();
        const test::Run r = test::runCli({"compare", "--port", nvs.device, "--port", geos.device,
                                          "--duration", "8", "--json"},
                                         {}, 60000);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject told =
                QJsonDocument::fromJson(r.out).object()["receivers"].toArray()[1].toObject();
        QVERIFY2(std::abs(test::compareMean(told, "east") - p.east.mean) < 0.05, r.out.constData());
        QVERIFY2(std::abs(test::compareMean(told, "north") - p.north.mean) < 0.05,
                 r.out.constData());
        QVERIFY2(std::abs(test::compareMean(told, "up") - p.up.mean) < 0.05, r.out.constData());
        QVERIFY2(std::abs(test::compareCn0(told, "GPS") - gps) < 1, r.out.constData());
        QVERIFY2(std::abs(test::compareCn0(told, "GLONASS") - glonass) < 1, r.out.constData());
        QVERIFY(windowMatches >= 8);

        // Back in the window, both recorded; the NV08C-RTK unplugged: the GeoS-5 goes on.
        a->link()->connectTo({SourceSpec::Kind::Serial, nvs.device, 0});
        b->link()->connectTo({SourceSpec::Kind::Serial, geos.device, 0});
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b), 40000);
        QString why;
        const QStringList files = w.recordAll(dir_.path(), &why);
        QVERIFY2(files.size() == 2, qPrintable(why));
        QVERIFY2(QFileInfo(files[1]).fileName().contains("GeoS"), qPrintable(files[1]));
        link::Connection *conn = b->link()->connection();
        const quint64 before = conn->bytesReceived();
        QTest::qWait(2000);
        nvs.stop(); // the pseudo-terminal goes away: unplugged
        QTRY_VERIFY_WITH_TIMEOUT(a->link()->state() != ReceiverLink::State::Connected, 10000);
        const quint64 epochs = b->state()->epochCount();
        QTRY_VERIFY_WITH_TIMEOUT(b->state()->epochCount() >= epochs + 3, 10000);
        QCOMPARE(b->link()->state(), ReceiverLink::State::Connected);
        QCOMPARE(b->link()->connection(), conn);
        const quint64 after = conn->bytesReceived();
        b->link()->stopRecording();
        a->link()->stopRecording();
        QFile recorded(files[1]);
        QVERIFY(recorded.open(QIODevice::ReadOnly));
        // Every byte the GeoS-5 sent while recording, and nothing else.
        QCOMPARE(quint64(recorded.size()), after - before);
        const QList<QByteArray> lines = recorded.readAll().split('\n');
        for (const QByteArray &line : lines)
            QVERIFY2(line.isEmpty() || line.startsWith('$'), line.constData());
        // Closing the unplugged one leaves the other running.
        w.closeReceiver(a);
        QCOMPARE(w.sessions().size(), 1);
        QCOMPARE(w.selectedSession(), b);
        const quint64 later = b->state()->epochCount();
        QTRY_VERIFY_WITH_TIMEOUT(b->state()->epochCount() > later, 5000);
        QVERIFY(!strip->isVisible());
    }

    // Three receivers: one healthy, one that hangs (silence=12@5: no output, no replies for
    // 12 s), one flooding junk (20 kB/s of random bytes between its sentences). The healthy and
    // the flooding one keep their views updating, their recordings byte-exact and their command
    // queues answering, at the same time; the hung one says so, is opened again after the
    // silence limit and is heard once it talks.
    void aHungAndAFloodingReceiverStayLocal() {
        SimProcess healthy({"--dialect", "nvs", "--baud", "115200"});
        SimProcess hung({"--dialect", "geostar", "--baud", "115200", "--faults", "silence=12@5"});
        SimProcess flooding({"--dialect", "nemerix", "--baud", "115200", "--faults", "junk=20000"});
        REQUIRE_SIM(healthy);
        REQUIRE_SIM(hung);
        REQUIRE_SIM(flooding);
        QSettings settings(dir_.filePath("faults.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, healthy.device, 115200},
                                   {SourceSpec::Kind::Serial, hung.device, 115200},
                                   {SourceSpec::Kind::Serial, flooding.device, 115200}});
        QCOMPARE(w.sessions().size(), 3);
        ui::ReceiverSession *a = w.sessions()[0], *b = w.sessions()[1], *c = w.sessions()[2];
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b) && connected(c), 30000);
        QSignalSpy aState(a->link(), &ReceiverLink::stateChanged),
                cState(c->link(), &ReceiverLink::stateChanged),
                bState(b->link(), &ReceiverLink::stateChanged);
        link::Connection *aConn = a->link()->connection(), *cConn = c->link()->connection();

        QVERIFY(QDir(dir_.path()).mkpath("faults"));
        QString why;
        const QStringList files = w.recordAll(dir_.filePath("faults"), &why);
        QVERIFY2(files.size() == 3, qPrintable(why));
        QByteArray fromA, fromC;
        connect(aConn->transport(), &link::Transport::bytesReceived,
                [&](const QByteArray &x) { fromA += x; });
        connect(cConn->transport(), &link::Transport::bytesReceived,
                [&](const QByteArray &x) { fromC += x; });

        // The hung one says so in its chip.
        auto *strip = w.findChild<app::ReceiversStrip *>();
        QTRY_VERIFY_WITH_TIMEOUT(b->link()->connection()->silentMs() >= 3000, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(strip->chips()[1]->status().startsWith("Silent for"), 3000);
        QCOMPARE(strip->chips()[1]->fix(), QString("No data"));
        QTRY_VERIFY_WITH_TIMEOUT(strip->chips()[2]->status().contains("KiB skipped"), 3000);

        // Meanwhile the three command queues work at once: the healthy and the flooding one
        // answer, the hung one does not.
        QSignalSpy aDone(a->link(), &ReceiverLink::commandFinished),
                bDone(b->link(), &ReceiverLink::commandFinished),
                cDone(c->link(), &ReceiverLink::commandFinished);
        auto probe = [this](const char *id) {
            const std::string_view p = registry_.find(id)->probeCommand;
            return QByteArray(p.data(), qsizetype(p.size()));
        };
        QVERIFY2(a->link()->send(probe("nvs"), &why), qPrintable(why));
        QVERIFY2(b->link()->send(probe("geostar"), &why), qPrintable(why));
        QVERIFY2(c->link()->send(probe("nemerix"), &why), qPrintable(why));
        const quint64 aEpochs = a->state()->epochCount(), cEpochs = c->state()->epochCount();
        QTRY_VERIFY_WITH_TIMEOUT(aDone.count() >= 1 && cDone.count() >= 1, 10000);
        QVERIFY2(aDone.first().at(1).toBool(), qPrintable(aDone.first().at(0).toString()));
        QVERIFY2(cDone.first().at(1).toBool(), qPrintable(cDone.first().at(0).toString()));
        QVERIFY(bDone.isEmpty() || !bDone.first().at(1).toBool());
        QTRY_VERIFY_WITH_TIMEOUT(a->state()->epochCount() >= aEpochs + 3 &&
                                         c->state()->epochCount() >= cEpochs + 3,
                                 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!bDone.isEmpty(), 20000);
        QVERIFY(!bDone.first().at(1).toBool());

        // The hung one is taken as lost after the silence limit, opened again, and heard.
        auto lostForSilence = [&bState] {
            for (const QList<QVariant> &x : bState)
                if (x.at(0).value<ReceiverLink::State>() == ReceiverLink::State::Reconnecting &&
                    x.at(1).toString().contains("no data"))
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(lostForSilence(), 20000);
        const quint64 bEpochs = b->state()->epochCount();
        QTRY_VERIFY_WITH_TIMEOUT(b->link()->state() == ReceiverLink::State::Connected &&
                                         b->state()->epochCount() > bEpochs + 2,
                                 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!strip->chips()[1]->status().startsWith("Silent"), 3000);

        // The others never lost their link; their recordings hold every byte they received.
        QCOMPARE(aState.count(), 0);
        QCOMPARE(cState.count(), 0);
        QCOMPARE(a->link()->connection(), aConn);
        QCOMPARE(c->link()->connection(), cConn);
        for (ui::ReceiverSession *s : w.sessions()) s->link()->stopRecording();
        for (const auto &[file, received] :
             {std::pair(files[0], fromA), std::pair(files[2], fromC)}) {
            link::Recording r;
            QVERIFY2(link::loadRecording(file, r, why), qPrintable(why));
            QCOMPARE(r.bytes, received);
        }
        QVERIFY(fromC.size() > 100'000); // the flood was recorded too
    }

    // With two receivers, every dock's tab reads whole at 1280x800, in English and in Russian
    // (the receiver named by its number: names cut seven tabs beside the fix to "Реш…").
    void dockTabsStayWhole_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << "en";
        QTest::newRow("ru") << "ru";
    }
    void dockTabsStayWhole() {
        QFETCH(QString, language);
        QTranslator ru;
        if (language == "ru") {
            if (!ru.load(QStringLiteral(GNSS_RU_QM)))
                QSKIP("no Russian translation built (Qt's linguist tools missing)");
            QCoreApplication::installTranslator(&ru);
        }
        QSettings settings(dir_.filePath("tabs-" + language + ".ini"), QSettings::IniFormat);
        // As gnss-workbench --sim nvs --sim geostar starts (maximised on the laptop's screen).
        app::MainWindow w(registry_, transports_, &settings);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.connectReceiversAtStart(
                {{SourceSpec::Kind::Simulator, "nvs"}, {SourceSpec::Kind::Simulator, "geostar"}});
        QTRY_VERIFY_WITH_TIMEOUT(connected(w.sessions()[0]) && connected(w.sessions()[1]), 10000);
        QTRY_VERIFY(w.dock("settingsDock")->windowTitle().contains(" · ")); // says which
        QTest::qWait(200);                                                  // the layout settles
        int bars = 0;
        for (QTabBar *bar : w.findChildren<QTabBar *>()) {
            // The dock areas' tab bars (the main window's own children).
            if (!bar->isVisible() || bar->count() < 2 || bar->parentWidget() != &w) continue;
            ++bars;
            QStringList tabs;
            for (int i = 0; i < bar->count(); ++i) tabs << bar->tabText(i);
            QVERIFY2(bar->sizeHint().width() <= bar->width(),
                     qPrintable(QStringLiteral("%1 px wanted, %2 px there: %3")
                                        .arg(bar->sizeHint().width())
                                        .arg(bar->width())
                                        .arg(tabs.join(" | "))));
        }
        QVERIFY(bars >= 3);
        // The tabs that name a receiver carry its colour; those that follow the selection not.
        auto tabIcon = [&w](const QString &dock) {
            const QString title = w.dock(dock)->windowTitle();
            for (QTabBar *bar : w.findChildren<QTabBar *>())
                for (int i = 0; i < bar->count(); ++i)
                    if (bar->tabText(i) == title) return bar->tabIcon(i);
            return QIcon();
        };
        QTRY_VERIFY(!tabIcon("settingsDock").isNull());
        QCOMPARE(tabIcon("settingsDock").pixmap(12).toImage().pixelColor(6, 6),
                 w.sessions()[0]->colour());
        QVERIFY(tabIcon("fixDock").isNull());
        QCoreApplication::removeTranslator(&ru);
    }

    // Work begun for a receiver stays with it when another is selected: a corrections stream
    // goes on feeding the receiver it was started for (the dock shows the selected one's, idle),
    // and a settings form with changes not yet applied keeps its receiver, pinned to it.
    void workStaysWithItsReceiver() {
        QTcpServer base; // a base's RTCM over TCP, one second of frames every 250 ms
        QVERIFY(base.listen(QHostAddress::LocalHost, 0));
        sim::RtcmBaseStation station;
        QList<QPointer<QTcpSocket>> clients;
        connect(&base, &QTcpServer::newConnection, this, [&] {
            while (QTcpSocket *c = base.nextPendingConnection()) clients << c;
        });
        QTimer tick;
        connect(&tick, &QTimer::timeout, this, [&] {
            station.advance(1.0);
            const QByteArray frames = QByteArray::fromStdString(station.takeOutput());
            for (const auto &c : clients)
                if (c) c->write(frames);
        });
        tick.start(250);

        QSettings settings(dir_.filePath("work.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart(
                {{SourceSpec::Kind::Simulator, "nvs"}, {SourceSpec::Kind::Simulator, "geostar"}});
        ui::ReceiverSession *a = w.sessions()[0], *b = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b), 10000);

        ui::CorrectionsRequest r;
        r.kind = ui::CorrectionsRequest::Kind::Tcp;
        r.host = "127.0.0.1";
        r.port = base.serverPort();
        QString why;
        QVERIFY2(w.corrections(a)->start(r, &why), qPrintable(why));
        auto forwarded = [](ui::ReceiverSession *s) -> std::uint64_t {
            const auto *f = s->link()->forwarderStats();
            return f ? f->framesForwarded : 0;
        };
        QTRY_VERIFY_WITH_TIMEOUT(forwarded(a) >= 3, 10000);
        auto *status = w.dock("correctionsDock")->findChild<QLabel *>("correctionsStatus");
        QVERIFY(status);
        QTRY_VERIFY2(status->text().contains("Receiving"), qPrintable(status->text()));

        // Settings for the first receiver, changed and not applied.
        config::SettingsEngine *engine = a->link()->settings();
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 20000);
        auto *form = qobject_cast<ui::SettingsView *>(w.dock("settingsDock")->widget());
        QVERIFY(form);
        ui::SettingEditor *editor = form->editor("rtk.ELGPS");
        QVERIFY(editor);
        QWidget *input = editor->input();
        input->setFocus();
        QTest::keyClick(input, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(input, "17");
        QTest::keyClick(input, Qt::Key_Tab);
        QVERIFY(form->isEdited("rtk.ELGPS"));
        // And a command typed in the console, not sent.
        auto *console = qobject_cast<ui::ConsoleView *>(w.dock("consoleDock")->widget());
        QVERIFY(console);
        auto *sendBox = console->findChild<QLineEdit *>("consoleInput");
        QVERIFY(sendBox);
        QTest::keyClicks(sendBox, "$PNVGVER");

        w.findChild<QAction *>("selectReceiver2")->trigger();
        QCOMPARE(w.dockSession(w.dock("correctionsDock")), b);
        // The stream goes on into the first receiver, none into the second.
        const std::uint64_t before = forwarded(a);
        QTRY_VERIFY_WITH_TIMEOUT(forwarded(a) >= before + 3, 10000);
        QCOMPARE(forwarded(b), std::uint64_t(0));
        QVERIFY(w.corrections(a)->active());
        QVERIFY(!w.corrections(b)->active());
        status = w.dock("correctionsDock")->findChild<QLabel *>("correctionsStatus");
        QVERIFY2(!status->text().contains("Receiving"), qPrintable(status->text()));
        // The form kept its receiver and its change.
        QCOMPARE(w.pinnedSession(w.dock("settingsDock")), a);
        QCOMPARE(qobject_cast<ui::SettingsView *>(w.dock("settingsDock")->widget()), form);
        QVERIFY(form->isEdited("rtk.ELGPS"));
        QVERIFY(w.dock("settingsDock")->windowTitle().contains("#1"));
        QCOMPARE(w.pinnedSession(w.dock("consoleDock")), a);
        QCOMPARE(console->typedCommand(), QString("$PNVGVER"));
        // The docks without work follow the selection.
        QCOMPARE(w.dockSession(w.dock("skyDock")), b);

        // Back on the first: its stream's state is shown again.
        w.findChild<QAction *>("selectReceiver1")->trigger();
        status = w.dock("correctionsDock")->findChild<QLabel *>("correctionsStatus");
        QTRY_VERIFY2(status->text().contains("Receiving"), qPrintable(status->text()));
        w.corrections(a)->stop();
    }

    // The connection bar's items that ask for their source (a port by its path, TCP, gpsd, a
    // log): what is given is the source chosen, for Connect and Add receiver; a cancel goes back
    // to the source chosen before.
    void anItemThatAsksForItsSourceChoosesIt_data() {
        QTest::addColumn<QString>("action");
        QTest::addColumn<QString>("given"); // empty: the dialog is cancelled
        QTest::addColumn<QString>("chosen");
        const QString log = dir_.filePath("yesterday.nmea");
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("$GPGGA,,,,,,0,00,,,M,,M,,*66\r\n");
        using K = SourceSpec::Kind;
        QTest::newRow("a port by its path")
                << "port?"
                << "/dev/serial/by-id/usb-NVS-if00"
                << SourceSpec{K::Serial, "/dev/serial/by-id/usb-NVS-if00", 0}.toString();
        QTest::newRow("TCP") << "tcp?"
                             << "192.0.2.7:5017" << SourceSpec{K::Tcp, "192.0.2.7:5017"}.toString();
        QTest::newRow("gpsd") << "gpsd?"
                              << "localhost:2948/dev/ttyUSB1"
                              << SourceSpec{K::Gpsd, "localhost:2948/dev/ttyUSB1"}.toString();
        QTest::newRow("a log") << "replay?" << log << SourceSpec{K::Replay, log}.toString();
        QTest::newRow("cancelled")
                << "port?" << QString() << SourceSpec{K::Simulator, "geostar"}.toString();
        // Refused when given, with why, and the source before kept.
        QTest::newRow("TCP without a port")
                << "tcp?"
                << "192.0.2.7" << SourceSpec{K::Simulator, "geostar"}.toString();
    }
    void anItemThatAsksForItsSourceChoosesIt() {
        QFETCH(QString, action);
        QFETCH(QString, given);
        QFETCH(QString, chosen);
        QSettings settings(dir_.filePath("ask.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        auto [bar, source] = sourceBar(w, {SourceSpec::Kind::Simulator, "geostar"});
        bool asked = false;
        QString warned; // what a message box after the dialog said
        // Answers each dialog as it comes, while the bar's handler runs (it returns when the
        // last one is closed).
        QTimer answer;
        answer.setInterval(20);
        connect(&answer, &QTimer::timeout, this, [&] {
            QWidget *modal = QApplication::activeModalWidget();
            if (auto *box = qobject_cast<QMessageBox *>(modal)) {
                warned = box->text();
                box->accept();
            } else if (auto *d = qobject_cast<QInputDialog *>(modal)) {
                asked = true;
                d->setTextValue(given);
                given.isEmpty() ? d->reject() : d->accept();
            } else if (auto *d = qobject_cast<QFileDialog *>(modal)) {
                asked = true;
                d->selectFile(given);
                static_cast<QDialog *>(d)->accept(); // QFileDialog's own is protected
            }
        });
        answer.start();
        source->setCurrentIndex(source->findData(action)); // as a click on the item does
        emit source->activated(source->currentIndex());
        answer.stop();
        QVERIFY2(asked, "no dialog asked for the source");
        const bool refused = QByteArray(QTest::currentDataTag()).contains("without");
        QVERIFY2(refused == warned.contains("HOST:PORT"), qPrintable(warned));
        QCOMPARE(bar->selection().toString(), chosen);
        QVERIFY(!source->currentData().toString().endsWith('?'));
    }

    // The wheel and the arrow keys do not step through the source list (they would open a
    // dialog on passing "Port by path…"): the wheel does nothing, an arrow opens the list.
    void theSourceListIsChosenFromWhenOpened() {
        QSettings settings(dir_.filePath("wheel.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        // The last source before the items.
        auto [bar, source] = sourceBar(w, {SourceSpec::Kind::Simulator, "nmea"});
        const QString before = bar->selection().toString();
        const QPointF at = QPointF(source->rect().center());
        for (int i = 0; i < 6; ++i) {
            QWheelEvent down(at, source->mapToGlobal(at), {}, {0, -120}, Qt::NoButton,
                             Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(source, &down);
        }
        QCOMPARE(bar->selection().toString(), before);
        QVERIFY(!QApplication::activeModalWidget());
        source->setFocus();
        QTest::keyClick(source, Qt::Key_Down);
        QCOMPARE(bar->selection().toString(), before);
        QVERIFY(!QApplication::activeModalWidget());
        QTRY_VERIFY(source->view()->isVisible()); // the list, to choose from
        source->hidePopup();
    }

    // The set of receivers comes back at the next start, with their names and pinned docks.
    void theSetOfReceiversIsRestored() {
        QSettings settings(dir_.filePath("restore.ini"), QSettings::IniFormat);
        {
            app::MainWindow w(registry_, transports_, &settings);
            w.connectReceiversAtStart({{SourceSpec::Kind::Simulator, "nvs"},
                                       {SourceSpec::Kind::Simulator, "geostar"}});
            w.sessions()[1]->setGivenName("Rover");
            QVERIFY(w.duplicateDock("fix", w.sessions()[1]));
            w.pinDock(w.dock("skyDock"), w.sessions()[1]);
            w.saveLayout();
        }
        app::MainWindow w(registry_, transports_, &settings);
        w.connectAtStart(SourceSpec{});
        QCOMPARE(w.sessions().size(), 2);
        QCOMPARE(w.sessions()[0]->link()->source().toString(), QString("sim:nvs"));
        QCOMPARE(w.sessions()[1]->link()->source().toString(), QString("sim:geostar"));
        QCOMPARE(w.sessions()[1]->name(), QString("Rover"));
        QCOMPARE(w.pinnedSession(w.dock("skyDock")), w.sessions()[1]);
        QDockWidget *second = w.dock("fixDock-2");
        QVERIFY(second);
        QCOMPARE(w.pinnedSession(second), w.sessions()[1]);
        QVERIFY(second->windowTitle().contains("#2"));
    }
};

QTEST_MAIN(TstReceiversWindow)
#include "tst_receivers_window.moc"
