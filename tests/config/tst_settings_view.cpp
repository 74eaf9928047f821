// The settings dock, offscreen, on the in-process simulator: a page per schema group with the
// right editor per type, receiver values and write-only marks, edits highlighted and applied,
// BASEXYZ ⇄ BASEBLH conversion, presets, confirmed actions, a profile's difference.
#include "dialect_rows.h"
#include "engine_rig.h"

#include "nvs/sim/nvs_sim_receiver.h"
#include "settings/setting_editors.h"
#include "settings/settings_view.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <cmath>
#include <set>

using namespace gnss;
using namespace gnss::config;
using namespace gnss::config::test;
using gnss::ui::CoordinateEditor;
using gnss::ui::SettingsView;

namespace {

QStringList schemaGroups(const Dialect &d) {
    QStringList out;
    for (const auto &def : d.settings) {
        const QString g = QString::fromUtf8(def.group.data(), int(def.group.size()));
        if (!def.key.starts_with("action.") && !out.contains(g)) out << g;
    }
    return out;
}

OperationReport waitFor(SettingsEngine &engine, const std::function<void()> &start) {
    QSignalSpy spy(&engine, &SettingsEngine::finished);
    start();
    if (spy.isEmpty()) spy.wait(30000);
    return engine.lastReport();
}

} // namespace

class TstSettingsView : public QObject {
    Q_OBJECT
private slots:
    void everyDialectGetsAPagePerGroup_data() { gnss::test::addSettingsDialectRows(); }
    void everyDialectGetsAPagePerGroup() {
        QFETCH(QString, dialect);
        EngineRig rig(dialect);
        SettingsView view(&rig.engine);
        QCOMPARE(view.pageNames(), schemaGroups(*rig.dialect));
        QVERIFY(!view.pageNames().contains("Actions"));
        auto *pages = view.findChild<QStackedWidget *>("settingPages");
        QCOMPARE(pages->count(), view.pageNames().size());
        for (const auto &def : rig.dialect->settings)
            if (!def.key.starts_with("action.")) QVERIFY(view.editor(std::string(def.key)));
    }

    void editorsFollowTheSettingTypes() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        auto *spin = view.findChild<QSpinBox *>("rtk.ELGPS");
        QVERIFY(spin);
        QCOMPARE(spin->minimum(), 0);
        QCOMPARE(spin->maximum(), 90);
        QCOMPARE(spin->suffix(), QString(" deg"));
        QVERIFY(!spin->toolTip().isEmpty());
        QVERIFY(view.findChild<QComboBox *>("rtk.MODE"));
        QVERIFY(view.findChild<QCheckBox *>("rtk.SYSGPS"));
        auto *real = view.findChild<QDoubleSpinBox *>("rtk.SFTRS");
        QVERIFY(real);
        QCOMPARE(real->suffix(), QString(" m/s"));
        QVERIFY(view.findChild<QLineEdit *>("output.COM1"));
        auto *xyz = qobject_cast<CoordinateEditor *>(view.editor("rtk.BASEXYZ"));
        auto *blh = qobject_cast<CoordinateEditor *>(view.editor("rtk.BASEBLH"));
        QVERIFY(xyz && blh);
        QCOMPARE(int(xyz->kind()), int(CoordinateEditor::Kind::Ecef));
        QCOMPARE(int(blh->kind()), int(CoordinateEditor::Kind::Geodetic));
    }

    void receiverValuesAndWriteOnlyMarksAreShown() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        const auto r = waitFor(rig.engine, [&] { view.readAll(); });
        QVERIFY2(r.ok(), describe(r));
        QCOMPARE(view.findChild<QSpinBox *>("rtk.ELGPS")->value(), 5);
        QVERIFY(view.findChild<QLabel *>("receiver:port.COM1.baud")
                        ->text()
                        .contains("unknown (write-only)"));
        QVERIFY(view.findChild<QLabel *>("receiver:rtk.ELGPS")->text().endsWith("5"));
        QVERIFY(view.edits().empty());
    }

    void editsAreHighlightedAgainstTheReceiverAndApplied() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        auto *spin = view.findChild<QSpinBox *>("rtk.ELGPS");
        spin->setValue(12);
        QVERIFY(view.isEdited("rtk.ELGPS"));
        QVERIFY(view.editor("rtk.ELGPS")->property("edited").toBool());
        spin->setValue(5); // back to the receiver's value: no longer an edit
        QVERIFY(!view.isEdited("rtk.ELGPS"));
        spin->setValue(12);
        view.findChild<QComboBox *>("pps.reference")->setCurrentIndex(2);
        QCOMPARE(int(view.edits().size()), 2);

        const auto r = waitFor(rig.engine, [&] { view.applyEdits(); });
        QVERIFY2(r.ok(), describe(r));
        const auto *rx = static_cast<sim::NvsReceiver *>(rig.sim.receiver());
        QCOMPARE(rx->settings().value("rtk.ELGPS"), std::string("12"));
        QCOMPARE(rx->settings().value("pps.reference"), std::string("G"));
        QVERIFY(view.edits().empty());
        QVERIFY(!view.editor("rtk.ELGPS")->property("edited").toBool());
        auto *outcomes = view.findChild<QTreeWidget *>("settingOutcomes");
        QVERIFY(outcomes->topLevelItemCount() >= 2);
        QVERIFY(outcomes->topLevelItem(outcomes->topLevelItemCount() - 1)->childCount() >= 3);
    }

    void revertShowsTheReceiversValuesAgain() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        view.findChild<QSpinBox *>("rtk.ELGLO")->setValue(30);
        view.revert();
        QVERIFY(view.edits().empty());
        QCOMPARE(view.findChild<QSpinBox *>("rtk.ELGLO")->value(), 5);
    }

    void baseCoordinatesConvertBetweenXyzAndBlh() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        auto *xyz = qobject_cast<CoordinateEditor *>(view.editor("rtk.BASEXYZ"));
        auto *blh = qobject_cast<CoordinateEditor *>(view.editor("rtk.BASEBLH"));
        // 33.5 S 70.25 W 520 m, as XYZ; BLH filled from it.
        xyz->setValue("1799238.6454,-5011294.7024,-3500621.2953");
        blh->convertButton()->click();
        const wgs84::Geodetic g = blh->geodetic();
        QVERIFY(std::fabs(g.latDeg + 33.5) < 1e-8);
        QVERIFY(std::fabs(g.lonDeg + 70.25) < 1e-8);
        QVERIFY(std::fabs(g.height - 520.0) < 1e-3);
        QVERIFY(view.isEdited("rtk.BASEBLH"));
        // Southern and western hemispheres are letters, not minus signs.
        QCOMPARE(blh->findChildren<QComboBox *>().at(0)->currentText(), QString("S"));
        QCOMPARE(blh->findChildren<QComboBox *>().at(1)->currentText(), QString("W"));
        // And back.
        xyz->setValue("0,0,0");
        xyz->convertButton()->click();
        QVERIFY(xyz->value().startsWith("1799238.645"));
    }

    void aPresetLoadsItsValuesAsEdits() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        view.loadPreset("Moving base with heading");
        QVERIFY(view.isEdited("rtk.MODE"));
        QVERIFY(!view.isEdited("rtk.SYSGPS")); // already 1 on the receiver
        QCOMPARE(view.findChild<QComboBox *>("rtk.MODE")->currentData().toString(), QString("4"));
    }

    void actionsAskFirst() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        int asked = 0;
        view.setConfirm([&](const QString &, const QString &) {
            ++asked;
            return false;
        });
        const auto before = rig.queue.history().size();
        view.runAction(Action::SaveToFlash);
        QCOMPARE(asked, 1);
        QTest::qWait(100);
        QCOMPARE(rig.queue.history().size(), before);
        view.setConfirm([&](const QString &, const QString &) { return true; });
        QVERIFY(waitFor(rig.engine, [&] { view.runAction(Action::SaveToFlash); }).ok());
        QVERIFY(rig.queue.history().last().sentence.startsWith("$PNVGCFG,W*"));
    }

    void anImportedProfileShowsItsDifferenceAsEdits() {
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        Profile p = rig.engine.exportProfile();
        for (auto &kv : p.values)
            if (kv.key == "rtk.ELSBAS") kv.value = "25";
        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        QVERIFY(saveProfile(path, p, nullptr));
        QString error;
        QVERIFY2(view.importProfile(path, &error), qPrintable(error));
        auto *diff = view.findChild<QTreeWidget *>("profileDiff");
        QCOMPARE(diff->topLevelItemCount(), 1);
        QCOMPARE(diff->topLevelItem(0)->text(0), QString("rtk.ELSBAS"));
        QVERIFY(view.isEdited("rtk.ELSBAS"));
        QVERIFY(waitFor(rig.engine, [&] { view.applyEdits(); }).ok());
        QVERIFY(rig.engine.diff(p).empty());
    }

    // Profile > Import of a profile that cannot be applied: its error, no edit loaded (so Apply
    // has nothing to send), nothing sent.
    void aProfileThatCannotBeAppliedLoadsNothing_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("why");
        auto profile = [](const QByteArray &dialect, const QByteArray &model,
                          const QByteArray &values) {
            return "{\"format\":\"gnss-workbench-settings\",\"version\":1,\"dialect\":\"" +
                   dialect + "\",\"model\":\"" + model + "\",\"values\":{" + values + "}}";
        };
        QTest::newRow("not a profile") << QByteArray("<html>") << "not a settings profile";
        QTest::newRow("another dialect")
                << profile("geostar", "GeoS-5M", R"("nav.ELEV":"5")")
                << "the profile is for dialect 'geostar', the receiver speaks 'nvs'";
        QTest::newRow("another model") << profile("nvs", "NV08C-CSM", R"("rtk.ELSBAS":"25")")
                                       << "the profile is for the NV08C-CSM, the receiver is a";
        QTest::newRow("out of range") << profile("nvs", "", R"("rtk.ELSBAS":"25","rtk.SNR":"150")")
                                      << "rtk.SNR: 150 is out of range";
        QTest::newRow("an unknown key")
                << profile("nvs", "", R"("rtk.ELSBAS":"25","nav.ELEV":"5")") << "nav.ELEV";
    }
    void aProfileThatCannotBeAppliedLoadsNothing() {
        QFETCH(QByteArray, json);
        QFETCH(QString, why);
        EngineRig rig("nvs");
        SettingsView view(&rig.engine);
        QVERIFY(waitFor(rig.engine, [&] { view.readAll(); }).ok());
        QVERIFY(!rig.engine.identity().model.empty()); // known, so another one is seen
        const auto sent = rig.queue.history().size();
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(json) == json.size());
        f.close();
        QString error;
        QVERIFY(!view.importProfile(path, &error));
        QVERIFY2(error.contains(why), qPrintable(error));
        QVERIFY(!view.isEdited("rtk.ELSBAS"));
        QCOMPARE(view.findChild<QTreeWidget *>("profileDiff")->topLevelItemCount(), 0);
        view.applyEdits(); // nothing to apply
        QTest::qWait(50);
        QCOMPARE(rig.queue.history().size(), sent);
    }
};

QTEST_MAIN(TstSettingsView)
#include "tst_settings_view.moc"
