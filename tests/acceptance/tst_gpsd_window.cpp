// The real MainWindow on a 1280x800 screen with a receiver that gpsd holds: gnss-sim's simulated
// NV08C-RTK on a pseudo-terminal, Debian's gpsd reading it on 127.0.0.1, and the window started
// as `gnss-workbench --gpsd 127.0.0.1:PORT` starts it. The views fill (fix, satellites, sky
// plot), the connection bar names the gpsd source, and the two places that send commands say
// why they cannot: the console's send box is off with "gpsd owns the port" beside it, and the
// settings dock says the same above its disabled buttons. Skipped when gpsd is not installed.
#include "gpsd_process.h"
#include "laptop_window.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "session/receiver_link.h"
#include "sim_process.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStatusBar>
#include <QTest>

using namespace gnss;
using gnss::app::SourceSpec;
using gnss::link::test::GpsdProcess;
using gnss::link::test::SimProcess;
using gnss::session::ReceiverLink;

class TstGpsdWindow : public QObject {
    Q_OBJECT
private slots:
    void aGpsdSourceFillsTheViewsAndSaysWhyNothingIsSent() {
        if (link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        if (link::test::gpsdPath().isEmpty()) QSKIP("gpsd is not installed (Debian package gpsd)");
        SimProcess sim({"--dialect", "nvs", "--baud", "115200"});
        if (!sim.ok()) QSKIP(qPrintable("gnss-sim did not start: " + sim.error));
        GpsdProcess gpsd(sim.device, 115200);
        QVERIFY2(gpsd.ok(), qPrintable(gpsd.error));

        gnss::test::LaptopWindow window;
        app::MainWindow &w = window.w;
        const SourceSpec spec{SourceSpec::Kind::Gpsd,
                              QStringLiteral("127.0.0.1:%1").arg(gpsd.port)};
        w.connectAtStart(spec);
        QTRY_COMPARE_WITH_TIMEOUT(w.link()->state(), ReceiverLink::State::Connected, 10000);
        QVERIFY2(w.link()->stateText().contains("gpsd"), qPrintable(w.link()->stateText()));
        const auto *source = w.findChild<QComboBox *>("sourceCombo");
        QVERIFY(source);
        QVERIFY2(source->currentText().contains("gpsd"), qPrintable(source->currentText()));
        QCOMPARE(SourceSpec::fromString(source->currentData().toString()).kind,
                 SourceSpec::Kind::Gpsd);
        QVERIFY(source->findData("gpsd?") >= 0); // "gpsd…" is offered beside "TCP…"

        // The views fill from the sentences gpsd relays.
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->epochCount() >= 3, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->state().epoch.lat.has_value(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.satelliteModel()->rowCount() > 5, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.session()->dialect() && w.session()->dialect()->id == "nvs",
                                 20000);

        // The console's send box is off, and says why.
        auto *console = w.dock("consoleDock");
        QVERIFY(console);
        w.showDock("console");
        auto *input = console->findChild<QLineEdit *>("consoleInput");
        auto *send = console->findChild<QPushButton *>("consoleSend");
        auto *note = console->findChild<QLabel *>("consoleSendNote");
        QVERIFY(input && send && note);
        QVERIFY(!input->isEnabled());
        QVERIFY(!send->isEnabled());
        QVERIFY(note->isVisible());
        QVERIFY2(note->text().contains("gpsd owns the port"), qPrintable(note->text()));
        QVERIFY2(input->placeholderText().contains("gpsd owns the port"),
                 qPrintable(input->placeholderText()));
        // Nothing is sent: the receiver link refuses with the same words, before the queue.
        QString why;
        QVERIFY(!w.link()->send("$PNVGVER*4E", &why));
        QVERIFY2(why.contains("gpsd owns the port"), qPrintable(why));
        QVERIFY(w.link()->connection()->commands()->history().isEmpty()); // no probe either

        // The settings dock: the form of the dialect recognised, its buttons off, the note above.
        QVERIFY(w.showDock("settings"));
        auto *settingsDock = w.dock("settingsDock");
        auto *settingsNote = settingsDock->findChild<QLabel *>("settingsSendNote");
        auto *read = settingsDock->findChild<QPushButton *>("settingsRead");
        QVERIFY(settingsNote && read);
        QTRY_VERIFY(settingsNote->isVisible());
        QVERIFY2(settingsNote->text().contains("gpsd owns the port"),
                 qPrintable(settingsNote->text()));
        QVERIFY(!read->isEnabled());
    }
};

QTEST_MAIN(TstGpsdWindow)
#include "tst_gpsd_window.moc"
