// The corrections path in the real MainWindow on a 1280x800 screen, as a user takes it: the
// simulated NV08C-RTK on a pseudo-terminal (a real rover: autonomous until RTCM arrives), the
// corrections dock filled in with the test's NTRIP 2 caster, Start clicked. The receiver goes
// to RTK fixed, the dock lists every message type with its rate and age, the base position and
// the distance, the frames forwarded, and the receiver's own RTCM counts; the caster got the
// receiver's fix as GGA. A refused request is said in the dock before anything starts.
#include "gui/corrections_controller.h"
#include "laptop_window.h"
#include "models/receiver_state_model.h"
#include "rtcm_fixtures.h"
#include "session/receiver_link.h"
#include "sim_process.h"
#include "test_caster.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

using namespace gnss;
using gnss::app::SourceSpec;
using gnss::link::test::SimProcess;
using gnss::session::ReceiverLink;

class TstCorrectionsWindow : public QObject {
    Q_OBJECT
private slots:
    void aCastersCorrectionsTakeTheRoverToRtkFixed() {
        if (link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimProcess rover({"--dialect", "nvs", "--speed", "5", "--baud", "460800"});
        if (!rover.ok()) QSKIP(qPrintable("gnss-sim did not start: " + rover.error));
        corrections_test::TstCaster caster;
        QVERIFY(caster.listen());
        const QList<QByteArray> epochs = corrections_test::baseEpochs(60);
        int next = 0;
        QTimer pump; // one base epoch a second to whoever streams
        connect(&pump, &QTimer::timeout, [&] {
            if (caster.streamingClients() >= 1 && next < epochs.size()) caster.send(epochs[next++]);
        });
        pump.start(1000);

        gnss::test::LaptopWindow window;
        app::MainWindow &w = window.w;
        w.connectAtStart(SourceSpec{SourceSpec::Kind::Serial, rover.device, 460800});
        QTRY_COMPARE_WITH_TIMEOUT(w.link()->state(), ReceiverLink::State::Connected, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->state().epoch.lat.has_value(), 15000);
        QTest::qWait(2000); // ten simulated seconds: still autonomous, no corrections yet
        QVERIFY(w.stateModel()->state().epoch.fix != FixType::RtkFloat &&
                w.stateModel()->state().epoch.fix != FixType::RtkFixed);

        QVERIFY(w.showDock("corrections"));
        QDockWidget *dock = w.dock("correctionsDock");
        QVERIFY(dock && dock->isVisible());
        auto *host = dock->findChild<QLineEdit *>("correctionsHost");
        auto *port = dock->findChild<QSpinBox *>("correctionsPort");
        auto *mount = dock->findChild<QLineEdit *>("correctionsMount");
        auto *user = dock->findChild<QLineEdit *>("correctionsUser");
        auto *password = dock->findChild<QLineEdit *>("correctionsPassword");
        auto *start = dock->findChild<QPushButton *>("correctionsStartStop");
        auto *status = dock->findChild<QLabel *>("correctionsStatus");
        QVERIFY(host && port && mount && user && password && start && status);

        // Incomplete: said in the dock, nothing started.
        host->clear();
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY2(status->text().contains("host"), qPrintable(status->text()));
        QVERIFY(!w.corrections()->active());

        QTest::keyClicks(host, "127.0.0.1");
        port->setValue(caster.port());
        mount->setText("MOUNT");
        user->setText("rover7");
        password->setText("s3cret-pw");
        // Kept only in the keychain when asked (offered when the build has one).
        auto *remember = dock->findChild<QCheckBox *>("correctionsRememberPassword");
        QVERIFY(remember);
        QCOMPARE(remember->isVisible(), app::CorrectionsController::keychainAvailable());
        if (remember->isVisible()) remember->setChecked(true);
        QTest::mouseClick(start, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains("Receiving"), 10000);
        QCOMPARE(start->text(), QString("Stop"));

        // The receiver uses them: float, then fixed (20 simulated seconds: 4 s here).
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->state().epoch.fix == FixType::RtkFixed, 30000);
        auto *types = dock->findChild<QTableWidget *>("correctionsTypes");
        QTRY_VERIFY_WITH_TIMEOUT(types->rowCount() >= 3, 5000); // 1005, 1074, 1084
        QCOMPARE(types->item(0, 0)->text(), QString("1005"));
        QVERIFY(types->item(1, 2)->text().toDouble() > 0.5); // about one a second
        auto *base = dock->findChild<QLabel *>("correctionsBase");
        QTRY_VERIFY2(base->text().contains("km"), qPrintable(base->text()));
        auto *forwarding = dock->findChild<QLabel *>("correctionsForwarding");
        QVERIFY2(forwarding->text().contains("Forwarded"), qPrintable(forwarding->text()));
        QVERIFY2(!forwarding->text().contains(" 0 frames"), qPrintable(forwarding->text()));
        auto *receiverSide = dock->findChild<QLabel *>("correctionsReceiver");
        QTRY_VERIFY2(receiverSide->text().contains("RTK fixed"), qPrintable(receiverSide->text()));
        QVERIFY(caster.uploads.contains("$GPGGA,")); // the receiver's fix went up

        // Remembered for next time, but never the password.
        QCOMPARE(window.settings.value("corrections/host").toString(), QString("127.0.0.1"));
        QCOMPARE(window.settings.value("corrections/mountpoint").toString(), QString("MOUNT"));
        QCOMPARE(window.settings.value("corrections/rememberPassword").toBool(),
                 remember->isVisible());
        window.settings.sync();
        QFile ini(window.settingsFile());
        QVERIFY(ini.open(QIODevice::ReadOnly));
        QVERIFY(!ini.readAll().contains("s3cret-pw"));

        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY(!w.corrections()->active());
        QCOMPARE(start->text(), QString("Start"));
    }
};

QTEST_MAIN(TstCorrectionsWindow)
#include "tst_corrections_window.moc"
