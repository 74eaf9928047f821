// The settings dock (offscreen) when the receiver is unplugged in the middle of applying its
// edits: gnss-sim on a pseudo-terminal drops the line as the second command arrives
// (hangupon=PNVGPPS). The form then shows no value it has not read back (the old one is gone,
// the edits stay edits) and says the settings are read back on return; when the link is back
// it shows what the receiver reports and the edits that took are edits no more.
// (tests/sim/tst_sim_apply_unplug checks the engine's reports command by command.)
#include "builtin_registry.h"
#include "sim_process.h"

#include "config/settings_engine.h"
#include "link/connection.h"
#include "link/serial_transport.h"
#include "settings/settings_view.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using namespace gnss;
using namespace gnss::config;
using namespace gnss::link;
using gnss::link::test::SimProcess;
using gnss::ui::SettingsView;

namespace {

// An NV08C in gnss-sim on a pseudo-terminal whose line drops when PNVGPPS arrives and comes back
// 0.5 s later (by the --link name), with a settings engine on the real serial link to it.
struct UnpluggedReceiver {
    QTemporaryDir dir;
    const QString link = dir.filePath("ttyGNSS");
    SimProcess sim{{"--dialect", "nvs", "--link", link, "--faults", "hangupon=PNVGPPS/0.5"}};
    const DialectRegistry &registry = gnss::test::builtinRegistry();
    const Dialect *nvs = registry.find("nvs");
    Connection conn{std::make_unique<SerialTransport>(SerialSettings{link, 115200}), registry};
    SettingsEngine engine;
    QSignalSpy finished{&engine, &SettingsEngine::finished};

    UnpluggedReceiver() {
        conn.commands()->setDialect(nvs);
        conn.setReconnectDelays(50, 200);
        engine.attach(&conn, nvs);
    }
};

} // namespace

class TstSettingsViewUnplug : public QObject {
    Q_OBJECT
private slots:
    void theFormShowsOnlyWhatWasReadBack() {
        UnpluggedReceiver rx;
        REQUIRE_SIM(rx.sim);
        SettingsEngine &engine = rx.engine;
        QSignalSpy &finished = rx.finished;
        QVERIFY(rx.conn.open());
        QTRY_VERIFY_WITH_TIMEOUT(rx.conn.transport()->isOpen(), 20000);
        SettingsView view(&engine);
        auto *elevation = view.findChild<QLabel *>("receiver:rtk.ELGPS");
        auto *reference = view.findChild<QLabel *>("receiver:pps.reference");
        auto *status = view.findChild<QLabel *>("settingsStatus");
        auto *outcomes = view.findChild<QTreeWidget *>("settingOutcomes");
        QVERIFY(elevation && reference && status && outcomes);
        // What the receiver has, read first (the elevation mask only: its query is no PNVGPPS).
        QVERIFY(engine.read({"rtk.ELGPS"}));
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 20000);
        QCOMPARE(elevation->text(), QStringLiteral("receiver: %1").arg(5));

        view.findChild<QSpinBox *>("rtk.ELGPS")->setValue(12);
        view.findChild<QComboBox *>("pps.reference")->setCurrentIndex(2); // "G"
        QCOMPARE(int(view.edits().size()), 2);
        view.applyEdits();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 2, 30000);
        // The elevation mask was taken but not read back: neither the old value nor the edit is
        // shown as the receiver's, and both edits stay edits.
        QCOMPARE(elevation->text(), QStringLiteral("receiver: %1").arg(QStringLiteral("\u2014")));
        QCOMPARE(reference->text(), QStringLiteral("receiver: %1").arg(QStringLiteral("\u2014")));
        QCOMPARE(int(view.edits().size()), 2);
        QVERIFY2(status->text().contains("read back when it returns"), qPrintable(status->text()));

        // Back: read back by itself, the form shows the receiver's values, the edits are done.
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 3, 30000);
        QCOMPARE(engine.lastReport().operation, Operation::ReadBack);
        QCOMPARE(elevation->text(), QStringLiteral("receiver: %1").arg(12));
        QCOMPARE(reference->text(), QStringLiteral("receiver: %1").arg("G"));
        QVERIFY(view.edits().empty());
        const QTreeWidgetItem *last = outcomes->topLevelItem(outcomes->topLevelItemCount() - 1);
        QCOMPARE(last->text(0), QStringLiteral("Read back after the link returned"));
        QVERIFY2(status->text().startsWith("Read back after the link returned: done"),
                 qPrintable(status->text()));
    }

    // A read of every setting that the line drops in (its PNVGPPS query) is read again when the
    // link returns: the form does not stay half read.
    void aReadTheLineDropsInIsDoneAgainOnReturn() {
        UnpluggedReceiver rx;
        REQUIRE_SIM(rx.sim);
        QVERIFY(rx.conn.open());
        QTRY_VERIFY_WITH_TIMEOUT(rx.conn.transport()->isOpen(), 20000);
        SettingsView view(&rx.engine);
        auto *reference = view.findChild<QLabel *>("receiver:pps.reference");
        auto *status = view.findChild<QLabel *>("settingsStatus");
        QVERIFY(reference && status);
        QVERIFY(rx.engine.read({}));
        QTRY_VERIFY_WITH_TIMEOUT(rx.finished.count() == 1, 30000);
        const OperationReport first = rx.engine.lastReport();
        QCOMPARE(first.operation, Operation::Read);
        QVERIFY(first.readBackOnReturn);
        QVERIFY(first.failedCommands() > 0);
        QCOMPARE(reference->text(), QStringLiteral("receiver: %1").arg(QStringLiteral("\u2014")));
        QVERIFY2(status->text().contains("read back when it returns"), qPrintable(status->text()));

        QTRY_VERIFY_WITH_TIMEOUT(rx.finished.count() == 2, 30000);
        const OperationReport again = rx.engine.lastReport();
        QCOMPARE(again.operation, Operation::Read);
        QVERIFY(!again.readBackOnReturn);
        QCOMPARE(again.failedCommands(), 0);
        QVERIFY2(reference->text() != QStringLiteral("receiver: %1").arg(QStringLiteral("\u2014")),
                 qPrintable(reference->text()));
        QVERIFY(rx.engine.pendingReadBack().empty());
    }
};

QTEST_MAIN(TstSettingsViewUnplug)
#include "tst_settings_view_unplug.moc"
