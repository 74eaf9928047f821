// A fourth receiver family, written only in this folder and registered with one line
// (acme_registry.h), goes through every surface: the decoder, gnss-cli decode, schema, encode and
// config (profiles and actions included) on its simulated receiver, and the real main window at
// laptop size: its docks, its settings form (read, edit, apply, verified), its presets, its
// roles (the sky plot's elevation mask) and its identity.
#include "acme_dialect.h"
#include "acme_registry.h"

#include "common/app_transports.h"
#include "config/settings_engine.h"
#include "core/settings_plan.h"
#include "core/stream_decoder.h"
#include "gui/main_window.h"
#include "link/source_spec.h"
#include "models/receiver_state_model.h"
#include "settings/setting_editors.h"
#include "settings/settings_view.h"
#include "sim/receiver.h"
#include "views/sky_plot_view.h"

#include <QAbstractItemView>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTreeWidget>

using namespace gnss;

namespace {

struct Run {
    int status = -1;
    QString out, err;
};

Run cli(const QStringList &args) {
    QProcess p;
    p.start(QStringLiteral(GNSS_CLI_ACME_PATH), args);
    Run r;
    if (!p.waitForFinished(60000)) return r;
    r.status = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

// Ten seconds of the simulated ACME receiver's output.
std::string simulatedLog() {
    auto rx = acme::simulatorsWithAcme().make("acme");
    std::string out;
    for (int i = 0; i < 20; ++i) {
        rx->advance(0.5);
        out += rx->takeOutput();
    }
    return out;
}

QString labelText(const QWidget *root, const char *name) {
    const auto *l = root->findChild<QLabel *>(QString::fromLatin1(name));
    return l ? l->text() : QString();
}

} // namespace

class TstFourthDialect : public QObject {
    Q_OBJECT
    const DialectRegistry registry_ = acme::registryWithAcme();
    const sim::SimulatorTable simulators_ = acme::simulatorsWithAcme();
    QTemporaryDir dir_;

private slots:
    void theDecoderRecognisesAndDecodesIt() {
        StreamDecoder decoder(registry_);
        int status = 0, identified = 0;
        decoder.feed(simulatedLog(), [&](const SentenceEvent &ev) {
            if (ev.message && message_cast<acme::Status>(*ev.message)) ++status;
        });
        (void)identified;
        QVERIFY(status >= 5);
        QVERIFY(decoder.dialect());
        QCOMPARE(decoder.dialect()->id, std::string_view("acme"));
    }

    void theSimulatorIsMadeByItsRecord() {
        const auto ids = simulators_.dialects();
        QVERIFY(std::find(ids.begin(), ids.end(), "acme") != ids.end());
        const std::string log = simulatedLog();
        QVERIFY(log.find("$PACMS,2,") != std::string::npos); // a fix after the first seconds
        QVERIFY(log.find("$GPGGA") != std::string::npos || log.find("$GNGGA") != std::string::npos);
    }

    void gnssCliDecodesItsLog() {
        const QString path = dir_.filePath("acme.nmea");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray::fromStdString(simulatedLog()));
        f.close();
        const Run r = cli({"decode", path});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.out.contains(R"("address":"PACMS")"), qPrintable(r.out.left(400)));
        QVERIFY(r.out.contains(R"("temperature":41.5)"));
        const Run d = cli({"decode", "--dialect", "acme", path});
        QCOMPARE(d.status, 0);
    }

    void gnssCliHelpNamesIt() {
        const Run r = cli({"--help"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.contains("acme"));
        QVERIFY(r.out.contains("ACME AX-1 (PACM...): a receiver family of the tests only"));
        QVERIFY(cli({"config", "--help"}).out.contains("acme"));
    }

    void gnssCliPrintsItsSchemaAndEncodesItsSettings() {
        const Run schema = cli({"schema", "acme"});
        QCOMPARE(schema.status, 0);
        const QJsonArray rows = QJsonDocument::fromJson(schema.out.toUtf8()).array();
        QCOMPARE(rows.size(), 3);
        QCOMPARE(rows.at(0).toObject().value("key").toString(), QString("acme.RATE"));

        const Run set = cli({"encode", "acme", "acme.RATE=10", "ELEV=15"});
        QCOMPARE(set.status, 0);
        QCOMPARE(set.out, QString("$PACMC,RATE,10*5F\r\n$PACMC,ELEV,15*42\r\n").remove('\r'));
        const Run query = cli({"encode", "acme", "--query", "acme.ELEV"});
        QCOMPARE(query.status, 0);
        QVERIFY(query.out.startsWith("$PACMQ,ELEV*"));
        const Run refused = cli({"encode", "acme", "acme.ELEV=61"});
        QCOMPARE(refused.status, 2); // a wrong request: nothing printed
        QVERIFY2(refused.err.contains("acme.ELEV: 61 is out of range; accepted: 0..60"),
                 qPrintable(refused.err));
        QVERIFY(refused.out.isEmpty());
    }

    void gnssCliConfiguresItsSimulatedReceiver() {
        const Run get = cli({"config", "--sim", "acme", "get"});
        QCOMPARE(get.status, 0);
        const QJsonObject read = QJsonDocument::fromJson(get.out.toUtf8()).object();
        QCOMPARE(read.value("dialect").toString(), QString("acme"));
        QCOMPARE(read.value("model").toString(), QString("AX-1"));
        QCOMPARE(read.value("values").toObject().value("acme.ELEV").toString(), QString("10"));

        const Run set = cli({"config", "--sim", "acme", "set", "acme.ELEV=20", "acme.RATE=5"});
        QVERIFY2(set.status == 0, qPrintable(set.out + set.err));
        QVERIFY(set.out.contains(R"("verdict":"verified")"));

        // A profile: exported from one receiver, applied to another (a fresh simulator, at its
        // defaults), then no difference left.
        const QString profile = dir_.filePath("acme-profile.json");
        QCOMPARE(cli({"config", "--sim", "acme", "export", profile}).status, 0);
        QFile p(profile);
        QVERIFY(p.open(QIODevice::ReadOnly));
        const QJsonObject saved = QJsonDocument::fromJson(p.readAll()).object();
        QCOMPARE(saved.value("dialect").toString(), QString("acme"));
        QCOMPARE(saved.value("values").toObject().value("acme.RATE").toString(), QString("1"));
        const Run apply = cli({"config", "--sim", "acme", "apply", profile});
        QVERIFY2(apply.status == 0, qPrintable(apply.out + apply.err));
        QCOMPARE(cli({"config", "--sim", "acme", "diff", profile}).status, 0);

        const Run save = cli({"config", "--sim", "acme", "action", "save"});
        QVERIFY2(save.status == 0, qPrintable(save.out + save.err));
        // Warm start is not among its actions: said so, nothing sent (a wrong request).
        QCOMPARE(cli({"config", "--sim", "acme", "action", "warm"}).status, 2);
    }

    void theRealWindowShowsItAndItsSettingsFormApplies() {
        QSettings settings(dir_.filePath("window.ini"), QSettings::IniFormat);
        const link::TransportFactory transports = app::makeTransportFactory(simulators_);
        app::MainWindow w(registry_, transports, &settings);
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.connectAtStart(app::SourceSpec{app::SourceSpec::Kind::Simulator, "acme"});

        // Its identity, its satellites, its fix: the docks follow a family they never heard of.
        QTRY_VERIFY_WITH_TIMEOUT(labelText(&w, "receiverIdentity").contains("AX-1"), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(
                w.findChild<QAbstractItemView *>("satelliteTable")->model()->rowCount() >= 6,
                20000);
        QTRY_VERIFY_WITH_TIMEOUT(labelText(&w, "fixLatitude").contains("N"), 20000);
        QVERIFY(w.stateModel()->state().reports.count("Status"));

        // Its settings form, read from the receiver.
        QDockWidget *dock = w.dock("settingsDock");
        QVERIFY(dock);
        dock->show();
        dock->raise();
        auto *view = qobject_cast<ui::SettingsView *>(dock->widget());
        auto *engine = w.findChild<config::SettingsEngine *>();
        QTRY_VERIFY_WITH_TIMEOUT(view->pageNames().contains("Navigation"), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(engine->receiverValue("acme.ELEV").has_value(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 20000);
        // The sky plot asks for the elevation-mask role, whatever the family calls it.
        QTRY_COMPARE(w.findChild<ui::SkyPlotView *>("skyPlot")->elevationMask(), 10.0);

        // A preset of the family, loaded from the Presets menu, then applied and verified.
        auto *presets = view->findChild<QToolButton *>("settingsPresets");
        QVERIFY(presets->isEnabled());
        QAction *urban = nullptr;
        for (QAction *a : presets->menu()->actions())
            if (a->text() == QStringLiteral("Urban canyon")) urban = a;
        QVERIFY(urban);
        urban->trigger();
        QVERIFY(view->isEdited("acme.ELEV"));
        QSignalSpy done(engine, &config::SettingsEngine::finished);
        auto *apply = view->findChild<QPushButton *>("settingsApply");
        QVERIFY(apply->isEnabled());
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(done.wait(20000));
        auto *outcomes = view->findChild<QTreeWidget *>("settingOutcomes");
        const QTreeWidgetItem *last = outcomes->topLevelItem(outcomes->topLevelItemCount() - 1);
        QVERIFY2(last->text(1) == QStringLiteral("done"), qPrintable(last->text(2)));
        QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(*engine->receiverValue("acme.ELEV")),
                                  QString("25"), 10000);
        QTRY_COMPARE(w.findChild<ui::SkyPlotView *>("skyPlot")->elevationMask(), 25.0);
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 20000);
    }
};

QTEST_MAIN(TstFourthDialect)
#include "tst_fourth_dialect.moc"
