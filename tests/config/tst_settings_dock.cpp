// The settings dock in the main window: present, and filled from the simulated receiver as soon
// as the connection knows its dialect (the real connection path, offscreen).
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/main_window.h"
#include "link/source_spec.h"
#include "settings/settings_view.h"

#include <QDockWidget>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

class TstSettingsDock : public QObject {
    Q_OBJECT
private slots:
    void theDockReadsTheReceiverOnConnect() {
        QTemporaryDir dir;
        QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
        const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
        const gnss::link::TransportFactory transports =
                gnss::app::makeTransportFactory(gnss::sim::builtinSimulators());
        gnss::app::MainWindow w(registry, transports, &settings);
        QDockWidget *dock = w.dock("settingsDock");
        QVERIFY(dock);
        auto *view = qobject_cast<gnss::ui::SettingsView *>(dock->widget());
        QVERIFY(view);
        QVERIFY(view->pageNames().isEmpty()); // no receiver yet
        w.connectAtStart(gnss::app::SourceSpec{gnss::app::SourceSpec::Kind::Simulator, "nvs"});
        QTRY_VERIFY_WITH_TIMEOUT(view->pageNames().contains("RTK engine"), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(
                view->findChild<QLabel *>("receiver:rtk.MODE") &&
                        view->findChild<QLabel *>("receiver:rtk.MODE")->text().endsWith(": 2"),
                15000);
        QCOMPARE(view->findChild<QSpinBox *>("rtk.ELGPS")->value(), 5);
        // Let the read finish: the window must not be destroyed with commands in flight (its
        // receiver link reports them to a status bar already gone).
        QTRY_VERIFY_WITH_TIMEOUT(
                view->findChild<QLabel *>("settingsStatus")->text().contains("done"), 15000);
    }
};

QTEST_MAIN(TstSettingsDock)
#include "tst_settings_dock.moc"
