// Several receivers in the real window at 1280x800: an NV08C-RTK at 38400 baud and a GeoS-5 at
// 57600, simulated on pseudo-terminals, both found with baud "auto" through the real QSerialPort.
// The GeoS-5 is told to differ (0.3 m east, -0.2 m north, 0.5 m up; GPS -3 dB, GLONASS +2 dB;
// G05 and R12 dropped) and both report the truth of one sky (--noise 0, --start now): the
// Compare dock shows what it was told (position within 5 cm, C/N0 within 1 dB), and so does
// gnss-cli compare on the same pair. Docks follow the selected receiver or stay pinned; one
// receiver unplugged leaves the other's epochs flowing and its recording byte-exact.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "cli_run.h"
#include "common/app_transports.h"
#include "compare_json.h"
#include "gui/main_window.h"
#include "gui/receivers_strip.h"
#include "link/connection.h"
#include "models/compare_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "session/receiver_link.h"
#include "sim_process.h"
#include "views/compare_view.h"
#include "views/fix_view.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

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
        // Both given as --port A --port B would: baud "auto" each.
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, nvs.device, 0},
                                   {SourceSpec::Kind::Serial, geos.device, 0}});
        QCOMPARE(w.sessions().size(), 2);
        ui::ReceiverSession *a = w.sessions()[0], *b = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b), 40000);
        QCOMPARE(a->link()->detectedBaud(), 38400);
        QCOMPARE(b->link()->detectedBaud(), 57600);
        // Named by model and port; the strip shows both, the first selected.
        QTRY_VERIFY_WITH_TIMEOUT(a->name().startsWith("NV08C") && a->name().endsWith(nvs.device),
                                 15000);
        QTRY_VERIFY_WITH_TIMEOUT(b->name().startsWith("GeoS") && b->name().endsWith(geos.device),
                                 15000);
        auto *strip = w.findChild<app::ReceiversStrip *>();
        QTRY_VERIFY(strip->isVisible() && strip->chips().size() == 2);
        QTRY_VERIFY(strip->chips()[1]->name().contains(b->name()));
        QVERIFY(a->colour() != b->colour());
        QCOMPARE(w.selectedSession(), a);

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
        QVERIFY(rover->windowTitle().contains(b->shortName()));
        QAction *second = w.findChild<QAction *>("selectReceiver2");
        QVERIFY(second);
        QCOMPARE(second->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_2));
        w.pinDock(fix, a);
        second->trigger();
        QCOMPARE(w.selectedSession(), b);
        QCOMPARE(w.dockSession(fix), a);
        QCOMPARE(w.dockSession(w.dock("skyDock")), b);
        QVERIFY(w.dock("settingsDock")->windowTitle().contains(b->shortName()));
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
        QVERIFY(second->windowTitle().contains("Rover"));
    }
};

QTEST_MAIN(TstReceiversWindow)
#include "tst_receivers_window.moc"
