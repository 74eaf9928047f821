// The dialects' texts in Russian: the catalog lupdate reads (translations/schema_texts.cpp) is the
// one the dialect records give today; every label, group, unit, option name, help text, action
// and preset of every built-in dialect, and every report title and field name their receivers
// give, has a Russian translation in the application's compiled .qm; and the settings form,
// built in Russian, shows them.
#include "core/settings_plan.h"
#include "engine_rig.h"

#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "config/refusal_text.h"
#include "config/schema_texts.h"
#include "schema_catalog.h"
#include "session_feed.h"
#include "settings/settings_view.h"
#include "vendor_test_rows.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QSpinBox>
#include <QToolButton>
#include <QTranslator>

using namespace gnss;
using namespace gnss::config::test;
using gnss::test::textRow;

namespace {

QString qs(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

} // namespace

class TstSchemaTranslations : public QObject {
    Q_OBJECT
    QTranslator russian_;

    QString ru(std::string_view dialect, std::string_view text) const {
        return russian_.translate(config::SchemaTexts::context(dialect).constData(),
                                  std::string(text).c_str());
    }

private slots:
    void initTestCase() { QVERIFY2(russian_.load(QStringLiteral(GNSS_RU_QM)), GNSS_RU_QM); }

    void theCatalogIsTheDialectsOfToday() {
        QFile f(QStringLiteral(GNSS_SCHEMA_CATALOG));
        QVERIFY2(f.open(QIODevice::ReadOnly), GNSS_SCHEMA_CATALOG);
        const std::vector<const Dialect *> dialects = builtinDialects();
        const QByteArray expected = QByteArray::fromStdString(
                schemaCatalogSource(dialects, registry(), sim::builtinSimulators()));
        QVERIFY2(f.readAll() == expected,
                 "translations/schema_texts.cpp is stale: run `cmake --build --preset dev "
                 "--target update_translations` and translate what it adds");
    }

    void everySchemaTextIsInRussian_data() {
        QTest::addColumn<QString>("dialect");
        for (const Dialect *d : builtinDialects())
            if (!d->settings.empty() || !d->actions.empty())
                QTest::newRow(d->id.data()) << qs(d->id);
    }
    void everySchemaTextIsInRussian() {
        QFETCH(QString, dialect);
        const Dialect *d = registry().find(dialect.toStdString());
        QVERIFY(d);
        QStringList missing;
        const std::vector<std::string> texts = schemaTexts(*d);
        for (const std::string &t : texts)
            if (ru(d->id, t).isEmpty()) missing << QString::fromStdString(t);
        QVERIFY2(missing.isEmpty(), qPrintable("no Russian for: " + missing.join(" | ")));
        QVERIFY(texts.size() > 50);
    }

    // The Receiver dock's report titles and field names, as the simulated receivers give them.
    void everyReportFieldIsInRussian() {
        QStringList missing;
        std::size_t texts = 0;
        for (const Dialect *d : builtinDialects())
            for (const std::string &t : reportTexts(*d, registry(), sim::builtinSimulators())) {
                ++texts;
                if (russian_.translate(kReportsContext, t.c_str()).isEmpty())
                    missing << QString::fromStdString(t);
            }
        QVERIFY2(missing.isEmpty(), qPrintable("no Russian for: " + missing.join(" | ")));
        QVERIFY(texts > 50);
    }

    // A refused value is said in Russian, with the dialect's own unit, through the engine as the
    // settings form applies it; the English text (the command line's) is unchanged.
    void refusalsAreInRussian_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("english");
        QTest::addColumn<QString>("russian");
        textRow("nvs range, unit",
                {"nvs", "rtk.ELGPS", "95", "rtk.ELGPS: 95 is out of range; accepted: 0..90 deg",
                 "rtk.ELGPS: 95 вне допустимого диапазона; допустимо: "
                 "0..90 град"});
        textRow("nvs list syntax",
                {"nvs", "output.COM1", "RMC:x",
                 "output.COM1: 'RMC:x' is not ADDRESS:RATE (rate in PVT intervals, >= 1)",
                 "output.COM1: «RMC:x» не в виде АДРЕС:ТЕМП (темп в интервалах PVT, >= 1)"});
        textRow("geostar not a number",
                {"geostar", "nav.ELEV", "high", "nav.ELEV: expected an integer, got 'high'",
                 "nav.ELEV: ожидается целое число, получено «high»"});
        textRow("nemerix beyond the schema",
                {"nemerix", "fix.timeZone", "25:00",
                 "fix.timeZone: '25:00' is not accepted; accepted: h:m with hours -13..13 and "
                 "minutes 0..59",
                 "fix.timeZone: «25:00» недопустимо; допустимо: ч:м, часы -13..13, минуты "
                 "0..59"});
    }
    void refusalsAreInRussian() {
        QFETCH(QString, dialect);
        QFETCH(QString, key);
        QFETCH(QString, value);
        EngineRig rig(dialect);
        const KeyValue kv{key.toStdString(), value.toStdString()};
        const EncodeResult enc = encodeSettings(*rig.dialect, std::span(&kv, 1));
        QTEST(QString::fromStdString(enc.error), "english");
        QTEST(config::refusalText(enc, rig.dialect->id), "english"); // no translator yet
        QCoreApplication::installTranslator(&russian_);
        const auto restore = qScopeGuard([this] { QCoreApplication::removeTranslator(&russian_); });
        QTEST(config::refusalText(enc, rig.dialect->id), "russian");
        const auto before = rig.queue.history().size();
        const config::OperationReport r = rig.apply({kv});
        QVERIFY(!r.ok());
        QVERIFY2(r.error.endsWith(config::refusalText(enc, rig.dialect->id)), qPrintable(r.error));
        QVERIFY2(!r.error.contains("nothing was sent"), qPrintable(r.error)); // the frame too
        QCOMPARE(rig.queue.history().size(), before);                         // nothing sent
    }

    // The console says what is wrong with a line in Russian: a field the decoder refuses, a
    // checksum, a sentence without enough fields.
    void consoleDiagnosticsAreInRussian() {
        QCoreApplication::installTranslator(&russian_);
        const auto restore = qScopeGuard([this] { QCoreApplication::removeTranslator(&russian_); });
        test::SessionFixture f;
        f.feedBytes("$GPGGA,120000.00,5550.6,N,03732.2,E,x,08,0.9,150.0,M,14.4,M,,*26\r\n"
                    "$GPGGA,120001.00,5550.6,N,03732.2,E,1,08,0.9,150.0,M,14.4,M,,*00\r\n"
                    "$GPZDA,120002.00*4B\r\n");
        f.session.refresh();
        QStringList tips;
        for (int row = 0; row < f.console.rowCount(); ++row)
            tips << f.console.data(f.console.index(row), Qt::ToolTipRole).toString();
        QCOMPARE(tips.size(), 3);
        QVERIFY2(tips[0].startsWith("поле 6 (quality)") &&
                         tips[0].contains(": не целое число: «x»"),
                 qPrintable(tips[0]));
        QVERIFY2(tips[1].startsWith("контрольная сумма не совпадает: передано 00, вычислено "),
                 qPrintable(tips[1]));
        QVERIFY2(tips[2].startsWith("ожидается не менее"), qPrintable(tips[2]));
    }

    void theSettingsFormSpeaksRussian_data() { everySchemaTextIsInRussian_data(); }
    void theSettingsFormSpeaksRussian() {
        QFETCH(QString, dialect);
        QCoreApplication::installTranslator(&russian_);
        const auto restore = qScopeGuard([this] { QCoreApplication::removeTranslator(&russian_); });
        EngineRig rig(dialect);
        ui::SettingsView view(&rig.engine);
        const Dialect &d = *rig.dialect;
        const auto settingsId = d.id;

        // The group list: every page under its Russian name.
        auto *groups = view.findChild<QListWidget *>("settingGroups");
        QVERIFY(groups && groups->count() > 0);
        for (int i = 0; i < groups->count(); ++i)
            QVERIFY2(!groups->item(i)->text().isEmpty(), qPrintable(groups->item(i)->text()));
        int rows = 0, enums = 0, units = 0;
        for (const SettingDef &def : d.settings) {
            auto *label = view.findChild<QLabel *>("label:" + qs(def.key));
            if (!label) continue; // actions are buttons
            ++rows;
            QVERIFY2(label->text().startsWith(ru(settingsId, def.label)),
                     qPrintable(label->text()));
            QCOMPARE(label->toolTip(), ru(settingsId, def.help));
            QVERIFY(groups->findItems(ru(settingsId, def.group), Qt::MatchExactly).size() == 1);
            if (!def.unit.empty()) {
                QVERIFY2(label->text().endsWith("(" + ru(settingsId, def.unit) + ")"),
                         qPrintable(label->text()));
                ++units;
            }
            if (auto *box = view.findChild<QComboBox *>(qs(def.key))) {
                for (const SettingOption &o : def.options)
                    if (o.label != o.value)
                        QVERIFY2(box->findText(ru(settingsId, o.label), Qt::MatchStartsWith) >= 0,
                                 qPrintable(qs(def.key) + ": " + qs(o.label)));
                ++enums;
            }
            if (auto *spin = view.findChild<QSpinBox *>(qs(def.key)); spin && !def.unit.empty())
                QCOMPARE(spin->suffix(), " " + ru(settingsId, def.unit));
        }
        QVERIFY(rows > 10);
        QVERIFY(enums > 0);
        QVERIFY(units > 0);
        // Restarts and presets, in the tool buttons' menus.
        auto menuTexts = [&](const char *button) {
            QStringList out;
            auto *b = view.findChild<QToolButton *>(button);
            if (b && b->menu())
                for (QAction *a : b->menu()->actions()) out << a->text();
            return out;
        };
        const QStringList resets = menuTexts("settingsReset");
        for (const ActionDef &a : d.actions)
            if (a.action != ReceiverAction::SaveToFlash &&
                a.action != ReceiverAction::RestoreDefaults)
                QVERIFY2(resets.contains(ru(settingsId, a.label)), qPrintable(resets.join(", ")));
        const QStringList presets = menuTexts("settingsPresets");
        for (const Preset &p : d.presets) QVERIFY(presets.contains(ru(settingsId, p.name)));
    }
};

QTEST_MAIN(TstSchemaTranslations)
#include "tst_schema_translations.moc"
