// The Base station dock in the real window at 1280x800, with two simulated NV08C-RTKs on
// pseudo-terminals (baud "auto"), ten times faster than real time: one is made a base from a
// survey-in by the workbench (until the mean is known to 0.3 m) and saved as a site, its RTCM
// on its COM2, each setting verified by reading it back; its COM2, opened as a third receiver,
// is served by the Serve dock's caster; the other, a rover, takes that caster in its
// Corrections dock and reaches RTK fixed. A GeoS-5 is said not to be able to be a base; a typed
// position 1 km away is set with the threshold warning shown, pressed while another operation
// on the receiver's settings runs (it waits for it).
#include "base/base_station_view.h"
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "cli_run.h"
#include "common/app_transports.h"
#include "config/settings_engine.h"
#include "gui/main_window.h"
#include "gui/serve_controller.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "serve/serve_view.h"
#include "session/receiver_link.h"
#include "sim_process.h"
#include "sites/site_store.h"
#include "window_children.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTableWidget>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace gnss;
using gnss::link::SourceSpec;
using gnss::link::test::SimProcess;
using gnss::session::ReceiverLink;

namespace {

using gnss::test::child;
constexpr auto connected = gnss::test::connectedWithEpochs;

QString verdicts(QListWidget *list) {
    QStringList lines;
    for (int i = 0; i < list->count(); ++i) lines << list->item(i)->text();
    return lines.join('\n');
}

// Types `text` into the next QInputDialog that opens and accepts it (the dialog runs its own
// event loop, in which this timer fires).
void answerNextInputDialog(const QString &text) {
    auto *timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, text] {
        auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
        if (!dialog) return;
        dialog->setTextValue(text);
        dialog->accept();
        timer->deleteLater();
    });
    timer->start();
}

} // namespace

class TstBaseWindow : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();
    link::TransportFactory transports_ = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QTemporaryDir dir_;

private slots:
    void aSurveyedBaseFeedsARoverToRtkFixed() {
        SimProcess base({"--dialect", "nvs", "--baud", "38400", "--speed", "10", "--com2"});
        REQUIRE_SIM(base);
        const QString com2 = gnss::link::test::firstLine(base.proc);
        QVERIFY(com2.startsWith("/dev/"));
        SimProcess rover({"--dialect", "nvs", "--speed", "10", "--seed", "2"});
        REQUIRE_SIM(rover);
        QSettings settings(dir_.filePath("window.ini"), QSettings::IniFormat);
        qputenv(sites::SiteStore::kDirectoryVariable, dir_.filePath("data").toUtf8());
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, base.device, 0},
                                   {SourceSpec::Kind::Serial, rover.device, 0}});
        ui::ReceiverSession *b = w.sessions()[0], *r = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(b) && connected(r), 40000);
        QTRY_VERIFY_WITH_TIMEOUT(b->dialect() && r->dialect(), 15000);
        w.selectReceiver(b);
        QVERIFY(w.showDock("base"));
        auto *view = w.dock("baseDock")->findChild<ui::BaseStationView *>();
        QVERIFY(view && view->isVisible() && view->canBeBase());
        QVERIFY(w.minimumSizeHint().height() <= 740);
        auto *status = child<QLabel>(view, "baseStatus");
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains("RTK rover"), 15000);

        // The workbench's survey-in, until the mean is known to 0.3 m.
        child<QComboBox>(view, "surveyGoal")->setCurrentIndex(1);
        child<QDoubleSpinBox>(view, "surveyGoalValue")->setValue(0.3);
        QTest::mouseClick(child<QPushButton>(view, "surveyStart"), Qt::LeftButton);
        QVERIFY(view->surveying());
        QTRY_VERIFY_WITH_TIMEOUT(!view->surveying(), 30000);
        const base::SurveyStatus s = view->survey().status();
        QVERIFY(s.count >= 10 && s.accuracy <= 0.3);
        QVERIFY(std::abs((s.mean.latDeg - 55.7512) * 111320) < 3);
        QVERIFY(child<QLabel>(view, "surveyText")->text().contains("σ east"));
        QVERIFY(!view->survey().history().empty());

        // Saved as a site: its name asked in a dialog; the survey's mean and accuracy kept.
        answerNextInputDialog("Roof mast");
        QTest::mouseClick(child<QPushButton>(view, "baseSaveSite"), Qt::LeftButton);
        sites::SiteList saved;
        QString why;
        QVERIFY2(sites::SiteStore().load(saved, why), qPrintable(why));
        const sites::Site *site = saved.find("roof MAST");
        QVERIFY(site);
        QCOMPARE(site->method, std::string("survey-in"));
        QVERIFY(std::abs((site->latDeg - s.mean.latDeg) * 111320) < 0.001);
        QVERIFY(site->accuracy && *site->accuracy <= 0.3);

        // Set: station 42, RTCM on COM2; every setting verified by reading it back.
        child<QSpinBox>(view, "baseStation")->setValue(42);
        auto *port = child<QComboBox>(view, "basePort");
        port->setCurrentIndex(port->findData(2));
        QTest::mouseClick(child<QPushButton>(view, "baseSet"), Qt::LeftButton);
        auto *list = child<QListWidget>(view, "baseVerdicts");
        QTRY_VERIFY2_WITH_TIMEOUT(verdicts(list).contains("rtk.BASEXYZ"),
                                  qPrintable(verdicts(list)), 15000);
        QVERIFY2(verdicts(list).contains("rtk.MODE: 1 (verified)"), qPrintable(verdicts(list)));
        QVERIFY2(verdicts(list).contains("rtk.BASEID: 42 (verified)"), qPrintable(verdicts(list)));
        QTRY_VERIFY2(status->text().contains("base at a set position") &&
                             status->text().contains("RTCM on port 2"),
                     qPrintable(status->text()));
        QVERIFY(!child<QLabel>(view, "baseWarning")->isVisible());

        // Its COM2 opened as a third receiver (baud "auto" finds it by its RTCM) and served from
        // the Serve dock on a free port; the rover takes it in its Corrections dock.
        ui::ReceiverSession *c2 = w.addReceiver({SourceSpec::Kind::Serial, com2, 0});
        QTRY_VERIFY_WITH_TIMEOUT(c2->link()->state() == ReceiverLink::State::Connected, 30000);
        // What it sends, in its own Corrections dock: station 42 at the position set on the base.
        w.selectReceiver(c2);
        QVERIFY(w.showDock("corrections"));
        auto *sent = w.dock("correctionsDock")->findChild<QLabel *>("correctionsBase");
        QTRY_VERIFY2_WITH_TIMEOUT(sent->text().contains("from the position set on " + b->name()),
                                  qPrintable(sent->text()), 15000);
        QVERIFY2(sent->text().contains("Base station 42") && sent->text().contains("0.00"),
                 qPrintable(sent->text()));
        QVERIFY(w.showDock("serve"));
        auto *serveView = w.dock("serveDock")->findChild<ui::ServeView *>();
        QVERIFY(serveView && serveView->isVisible());
        QVERIFY(w.minimumSizeHint().height() <= 740);
        auto *mounts = child<QTableWidget>(serveView, "serveMounts");
        QCOMPARE(mounts->rowCount(), 6); // each receiver's RTCM, and the corrections fed to it
        for (int i = 0; i < mounts->rowCount(); ++i)
            mounts->item(i, 0)->setCheckState(i == 4 ? Qt::Checked : Qt::Unchecked);
        QVERIFY(mounts->item(4, 0)->text().contains(c2->name()));
        mounts->item(4, 1)->setText("NVSB");
        child<QSpinBox>(serveView, "servePort")->setValue(0);
        QTest::mouseClick(child<QPushButton>(serveView, "serveCasterStartStop"), Qt::LeftButton);
        QVERIFY(w.serving()->casterRunning());
        const quint16 casterPort = w.serving()->caster()->port();
        QVERIFY(child<QLabel>(serveView, "serveCasterState")->text().contains("NVSB"));
        w.selectReceiver(r);
        QVERIFY(w.showDock("corrections"));
        QDockWidget *dock = w.dock("correctionsDock");
        dock->findChild<QLineEdit *>("correctionsHost")->setText("127.0.0.1");
        dock->findChild<QSpinBox *>("correctionsPort")->setValue(casterPort);
        dock->findChild<QLineEdit *>("correctionsMount")->setText("NVSB");
        QTest::mouseClick(dock->findChild<QPushButton *>("correctionsStartStop"), Qt::LeftButton);
        // The client listed with what it was sent.
        auto *clients = child<QTableWidget>(serveView, "serveClients");
        QTRY_VERIFY_WITH_TIMEOUT(clients->rowCount() == 1 && clients->item(0, 3) &&
                                         clients->item(0, 3)->text() == "NVSB",
                                 10000);
        QTRY_VERIFY_WITH_TIMEOUT(r->state()->state().epoch.fix == FixType::RtkFixed, 30000);
    }

    // A base's RTCM port opened as a receiver (baud "auto" finds it by its CRC-valid frames):
    // the Corrections dock shows what the base sends, its types, rates and station position.
    void theCorrectionsDockShowsWhatABaseSends() {
        SimProcess base({"--dialect", "nvs", "--baud", "115200", "--speed", "10", "--com2"});
        REQUIRE_SIM(base);
        const QString com2 = gnss::link::test::firstLine(base.proc);
        QVERIFY(com2.startsWith("/dev/"));
        const gnss::test::Run set = gnss::test::runCli(
                {"base", "--port", base.device, "--baud", "115200", "set", "--llh",
                 "55.7512,37.6184,166.6", "--station", "77", "--rtcm-port", "2"});
        QVERIFY2(set.exitCode == 0, set.err.constData());
        QSettings settings(dir_.filePath("window3.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, com2, 0}});
        QVERIFY(w.showDock("corrections"));
        QDockWidget *dock = w.dock("correctionsDock");
        auto *types = dock->findChild<QTableWidget *>("correctionsTypes");
        QTRY_VERIFY_WITH_TIMEOUT(types->rowCount() >= 3, 30000);
        QStringList numbers;
        for (int i = 0; i < types->rowCount(); ++i) numbers << types->item(i, 0)->text();
        QCOMPARE(numbers, (QStringList{"1002", "1005", "1010"}));
        QTRY_VERIFY(types->item(0, 2)->text().toDouble() > 5); // ten a second at ×10
        auto *status = dock->findChild<QLabel *>("correctionsStatus");
        QVERIFY2(status->text().contains("receiver itself"), qPrintable(status->text()));
        auto *station = dock->findChild<QLabel *>("correctionsBase");
        QTRY_VERIFY2(station->text().contains("Base station 77"), qPrintable(station->text()));
        QVERIFY(station->text().contains("55.75120"));
    }

    // The Serve dock's mistakes are said and nothing listens; a receiver shared on a raw port
    // reaches a client byte for byte; a client dropped from the list is disconnected.
    void theServeDockSharesAReceiver() {
        QSettings settings(dir_.filePath("window4.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart({{SourceSpec::Kind::Simulator, "nmea", 0}});
        QTRY_VERIFY_WITH_TIMEOUT(connected(w.sessions()[0]), 20000);
        QVERIFY(w.showDock("serve"));
        auto *view = w.dock("serveDock")->findChild<ui::ServeView *>();
        auto *mounts = child<QTableWidget>(view, "serveMounts");
        auto *state = child<QLabel>(view, "serveCasterState");
        auto *start = child<QPushButton>(view, "serveCasterStartStop");
        child<QSpinBox>(view, "servePort")->setValue(0);
        QVERIFY(mounts->item(0, 0)->checkState() == Qt::Unchecked); // it sends no RTCM
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY2(state->text().contains("Tick a stream"), qPrintable(state->text()));
        mounts->item(0, 0)->setCheckState(Qt::Checked);
        mounts->item(0, 1)->setText("bad name");
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY2(state->text().contains("bad name"), qPrintable(state->text()));
        QVERIFY(!w.serving()->casterRunning());
        mounts->item(0, 1)->setText("SIM");
        child<QLineEdit>(view, "serveUser")->setText("u");
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY2(state->text().contains("password"), qPrintable(state->text()));
        QVERIFY(!w.serving()->casterRunning());

        child<QSpinBox>(view, "serveRawPort")->setValue(0);
        QTest::mouseClick(child<QPushButton>(view, "serveRawStartStop"), Qt::LeftButton);
        QVERIFY(w.serving()->rawRunning());
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, w.serving()->raw()->port());
        QVERIFY(client.waitForConnected(3000));
        QByteArray got;
        QTRY_VERIFY_WITH_TIMEOUT((got += client.readAll()).contains("GGA,"), 10000);
        auto *clients = child<QTableWidget>(view, "serveClients");
        QTRY_COMPARE(clients->rowCount(), 1);
        QCOMPARE(clients->item(0, 0)->text(), QString("raw"));
        // Dropped from the list: the client is disconnected, the server goes on.
        auto *drop = child<QPushButton>(view, "serveDropClient");
        QVERIFY(!drop->isEnabled());
        clients->selectRow(0);
        QVERIFY(drop->isEnabled());
        QTest::mouseClick(drop, Qt::LeftButton);
        QTRY_COMPARE(client.state(), QAbstractSocket::UnconnectedState);
        QTRY_COMPARE(clients->rowCount(), 0);
        QVERIFY(w.serving()->rawRunning());
        client.connectToHost(QHostAddress::LocalHost, w.serving()->raw()->port());
        QVERIFY(client.waitForConnected(3000));
        QTRY_COMPARE(clients->rowCount(), 1);
        QTest::mouseClick(child<QPushButton>(view, "serveRawStartStop"), Qt::LeftButton);
        QVERIFY(!w.serving()->rawRunning());
        QTRY_COMPARE(client.state(), QAbstractSocket::UnconnectedState);
    }

    void aPositionPastTheThresholdIsWarnedOf() {
        QSettings settings(dir_.filePath("window2.ini"), QSettings::IniFormat);
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        w.connectReceiversAtStart({{SourceSpec::Kind::Simulator, "nvs", 0},
                                   {SourceSpec::Kind::Simulator, "geostar", 0}});
        ui::ReceiverSession *nvs = w.sessions()[0], *geos = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(nvs) && connected(geos), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(nvs->dialect() && geos->dialect(), 15000);
        // The settings and epochs arrive while the dock is put away (as at every start): the
        // status is not measured then (a label never laid out is narrow, its lines many), and
        // has the height of its lines once shown.
        QTRY_VERIFY_WITH_TIMEOUT(!nvs->link()->settings()->isBusy() &&
                                         nvs->state()->state().epoch.lat.has_value(),
                                 20000);
        QTest::qWait(500); // epochs while hidden
        QVERIFY(w.showDock("base"));
        auto *shown =
                child<QLabel>(w.dock("baseDock")->findChild<ui::BaseStationView *>(), "baseStatus");
        QTRY_VERIFY2(shown->text().contains("Position:"), qPrintable(shown->text()));
        QTest::qWait(100);
        QVERIFY2(shown->height() <=
                         shown->heightForWidth(shown->width()) + shown->fontMetrics().lineSpacing(),
                 qPrintable(QStringLiteral("%1 px for %2 px of text")
                                    .arg(shown->height())
                                    .arg(shown->heightForWidth(shown->width()))));
        w.selectReceiver(geos);
        QVERIFY(w.showDock("base"));
        auto *view = w.dock("baseDock")->findChild<ui::BaseStationView *>();
        QTRY_VERIFY(view && !view->canBeBase());
        QVERIFY(child<QLabel>(view, "baseUnsupported")->text().contains("cannot be a base"));

        w.selectReceiver(nvs);
        view = w.dock("baseDock")->findChild<ui::BaseStationView *>();
        QTRY_VERIFY(view && view->canBeBase());
        QTRY_VERIFY_WITH_TIMEOUT(nvs->state()->state().epoch.lat.has_value(), 20000);
        auto *pages = view->findChild<QStackedWidget *>();
        const int surveyHeight = pages->sizeHint().height();
        child<QComboBox>(view, "baseSource")->setCurrentIndex(2);
        // The known position's page is a few lines: no room kept for the survey's plot.
        QVERIFY2(pages->sizeHint().height() < surveyHeight / 2,
                 qPrintable(QStringLiteral("%1 px, the survey %2")
                                    .arg(pages->sizeHint().height())
                                    .arg(surveyHeight)));
        auto *position = child<QLineEdit>(view, "knownPosition");
        // Malformed: said, nothing sent.
        position->setText("95,37,150");
        QTest::mouseClick(child<QPushButton>(view, "baseSet"), Qt::LeftButton);
        auto *list = child<QListWidget>(view, "baseVerdicts");
        QVERIFY2(verdicts(list).contains("beyond 90"), qPrintable(verdicts(list)));
        // 1.1 km north of where it is (DMS): set, verified, and the warning shown. Pressed while
        // the engine reads every setting (as the Settings dock does on connect): it waits for
        // that read, then sets.
        position->setText("55°45'40.3\"N, 37°37'06.2\"E, 166.6");
        config::SettingsEngine *engine = nvs->link()->settings();
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 15000);
        // While the settings are read again their values go (forget() clears them as a read
        // does) and the status shrinks to a line: what is below it stays where it was, so that
        // Set base does not move from under the pointer.
        auto *status = child<QLabel>(view, "baseStatus");
        QTRY_VERIFY2(status->text().contains("Position:"), qPrintable(status->text()));
        auto *set = child<QPushButton>(view, "baseSet");
        QTest::qWait(100); // laid out
        const int setAt = set->mapTo(view, QPoint()).y();
        engine->forget();
        QVERIFY2(status->text().contains("not read yet"), qPrintable(status->text()));
        QTest::qWait(100);
        QCOMPARE(set->mapTo(view, QPoint()).y(), setAt);
        list->setFixedWidth(240); // a narrow dock (or a Russian line, twice as long)
        QTest::qWait(100);
        QVERIFY(engine->read());
        QTest::mouseClick(child<QPushButton>(view, "baseSet"), Qt::LeftButton);
        QVERIFY2(verdicts(list).contains("Waiting for the operation in progress"),
                 qPrintable(verdicts(list)));
        // A line longer than the list is wide wraps: the whole line in sight.
        list->doItemsLayout();
        const QRect line = list->visualItemRect(list->item(list->count() - 1));
        QVERIFY2(line.width() <= list->viewport()->width() &&
                         line.height() > 2 * list->fontMetrics().lineSpacing(),
                 qPrintable(QStringLiteral("%1 px wide, %2 high, in %3")
                                    .arg(line.width())
                                    .arg(line.height())
                                    .arg(list->viewport()->width())));
        list->setMinimumWidth(0);
        list->setMaximumWidth(QWIDGETSIZE_MAX);
        QTRY_VERIFY2_WITH_TIMEOUT(verdicts(list).contains("rtk.BASEXYZ"),
                                  qPrintable(verdicts(list)), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(child<QLabel>(view, "baseWarning")->isVisible(), 10000);
        QVERIFY(child<QLabel>(view, "baseWarning")->text().contains("no corrections"));
    }
};

QTEST_MAIN(TstBaseWindow)
#include "tst_base_window.moc"
