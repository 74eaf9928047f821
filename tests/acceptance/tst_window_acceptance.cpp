// Acceptance: the real MainWindow on a 1280x800 screen, used as a user uses it. A simulated
// NV08C-RTK on a pseudo-terminal talks at 38400 baud; the window connects with baud "auto"
// through the real QSerialPort, every dock shows data, the settings form can be read (every
// label whole, every editor at its size and inside the view, docked and floated), an edit made
// in the form and applied reaches the simulator (read back from it), the sky plot's labels do
// not collide, and a TCP source with nobody listening leaves the window responsive.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "config/settings_engine.h"
#include "gui/connection_bar.h"
#include "gui/main_window.h"
#include "link/connection.h"
#include "link/sentence_stream.h"
#include "loop_watch.h"
#include "models/console_model.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "session/receiver_link.h"
#include "settings/setting_editors.h"
#include "settings/settings_view.h"
#include "sim_process.h"
#include "tab_titles.h"
#include "views/charts_view.h"
#include "views/deviation_view.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDebug>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QLabel>
#include <QLineSeries>
#include <QListWidget>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QTabBar>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

using namespace gnss;
using gnss::app::SourceSpec;
using gnss::session::ReceiverLink;

namespace {

// Clicks the tab that shows `dock` when it is tabbed with others, as a user does.
bool clickTabOf(QMainWindow &w, QDockWidget *dock) {
    for (QTabBar *bar : w.findChildren<QTabBar *>()) {
        for (int i = 0; i < bar->count(); ++i) {
            if (bar->tabText(i) != dock->windowTitle() || !bar->isVisible()) continue;
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
            return true;
        }
    }
    return false; // not tabbed: it is shown already
}

QString labelText(const QWidget *root, const char *name) {
    const auto *l = root->findChild<QLabel *>(QString::fromLatin1(name));
    return l ? l->text() : QStringLiteral("<no %1>").arg(QString::fromLatin1(name));
}

// Why `w` cannot be read in full in `viewport` (empty when it can): narrower than it asks, or
// sticking out of the visible area.
QString cutOff(QWidget *w, QWidget *viewport) {
    if (!w->isVisible()) return QStringLiteral("hidden");
    if (w->width() < w->sizeHint().width())
        return QStringLiteral("width %1 < size hint %2").arg(w->width()).arg(w->sizeHint().width());
    const QRect r(w->mapTo(viewport, QPoint(0, 0)), w->size());
    if (r.left() < 0 || r.right() >= viewport->width())
        return QStringLiteral("x %1..%2 outside 0..%3")
                .arg(r.left())
                .arg(r.right())
                .arg(viewport->width());
    if (r.top() < 0 || r.bottom() >= viewport->height())
        return QStringLiteral("y %1..%2 outside 0..%3")
                .arg(r.top())
                .arg(r.bottom())
                .arg(viewport->height());
    return {};
}

} // namespace

class TstWindowAcceptance : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();
    link::TransportFactory transports_ = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QTemporaryDir dir_;
    std::unique_ptr<link::test::SimProcess> sim_;
    std::unique_ptr<QSettings> settings_;
    std::unique_ptr<app::MainWindow> w_;

    QDockWidget *dock(const char *name) { return w_->dock(QString::fromLatin1(name)); }

    // Checks every editor, label and receiver value of the settings form on every page.
    void checkSettingsFormReadable(ui::SettingsView *view, const QString &where) {
        auto *pages = view->findChild<QStackedWidget *>("settingPages");
        auto *list = view->findChild<QListWidget *>("settingGroups");
        auto *combo = view->findChild<QComboBox *>("settingGroupCombo");
        QVERIFY(pages && list && combo);
        QVERIFY2(pages->count() >= 3, qPrintable(where));
        QVERIFY2(list->isVisible() != combo->isVisible(), qPrintable(where));
        int checked = 0;
        for (int page = 0; page < pages->count(); ++page) {
            // Choose the group as a user does: in the list, or in the combo box.
            if (list->isVisible()) {
                const QRect r = list->visualItemRect(list->item(page));
                QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, r.center());
            } else {
                combo->setCurrentIndex(page);
            }
            QCOMPARE(pages->currentIndex(), page);
            auto *scroll = qobject_cast<QScrollArea *>(pages->currentWidget());
            QVERIFY(scroll);
            QCoreApplication::processEvents();
            auto *form = qobject_cast<QFormLayout *>(scroll->widget()->layout());
            QVERIFY(form);
            for (int row = 0; row < form->rowCount(); ++row) {
                auto *label =
                        qobject_cast<QLabel *>(form->itemAt(row, QFormLayout::LabelRole)->widget());
                QWidget *field = form->itemAt(row, QFormLayout::FieldRole)->widget();
                const QString key = label->property("settingKey").toString();
                // Scrolled to the row (label and editor), as a user scrolls to read it.
                const QRect span = label->geometry().united(field->geometry());
                scroll->ensureVisible(span.center().x(), span.center().y(), span.width() / 2 + 1,
                                      span.height() / 2 + 1);
                QCoreApplication::processEvents();
                if (field->minimumSizeHint().width() > scroll->viewport()->width() ||
                    label->sizeHint().width() > scroll->viewport()->width())
                    qWarning() << "too wide:" << key << field->minimumSizeHint()
                               << label->sizeHint() << scroll->viewport()->width();
                auto *editor = view->editor(key.toStdString());
                QVERIFY2(editor, qPrintable(key));
                auto *receiver = view->findChild<QLabel *>("receiver:" + key);
                for (QWidget *part : std::initializer_list<QWidget *>{label, editor, receiver}) {
                    const QString why = cutOff(part, scroll->viewport());
                    QVERIFY2(why.isEmpty(),
                             qPrintable(QStringLiteral("%1: %2 %3: %4")
                                                .arg(where, key, part->metaObject()->className(),
                                                     why)));
                }
                ++checked;
            }
        }
        QVERIFY2(checked >= 20, qPrintable(QString::number(checked)));
    }

private slots:
    void initTestCase() {
        QCOMPARE(QGuiApplication::primaryScreen()->geometry().size(), QSize(1280, 800));
        sim_ = std::make_unique<link::test::SimProcess>(
                QStringList{"--dialect", "nvs", "--baud", "38400", "--seed", "5"});
        if (!sim_->ok()) QSKIP(qPrintable("gnss-sim: " + sim_->error));
        settings_ = std::make_unique<QSettings>(dir_.filePath("s.ini"), QSettings::IniFormat);
        w_ = std::make_unique<app::MainWindow>(registry_, transports_, settings_.get());
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        // As from the command line with --port and no --baud: the connection bar's "auto".
        w_->connectAtStart(SourceSpec{SourceSpec::Kind::Serial, sim_->device, 0});
    }

    void theWindowFitsTheScreen() {
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        QVERIFY2(screen.contains(w_->frameGeometry()),
                 qPrintable(QStringLiteral("%1x%2").arg(w_->width()).arg(w_->height())));
    }

    void autoBaudFindsTheReceiverAndConnects() {
        auto *c = w_->link();
        QTRY_VERIFY_WITH_TIMEOUT(c->state() == ReceiverLink::State::Connected, 30000);
        QCOMPARE(c->detectedBaud(), 38400);
        QVERIFY2(c->stateText().contains("38400"), qPrintable(c->stateText()));
        QVERIFY2(c->detectionDetail().contains("38400 (valid NMEA)"),
                 qPrintable(c->detectionDetail()));
        QVERIFY2(labelText(w_.get(), "baudNote").contains("38400"),
                 qPrintable(labelText(w_.get(), "baudNote")));
        QTRY_VERIFY_WITH_TIMEOUT(w_->stateModel()->epochCount() >= 5, 20000);
    }

    void everyDockShowsData() {
        QTRY_VERIFY_WITH_TIMEOUT(!w_->stateModel()->state().identity.model.empty(), 15000);
        // Shown one after the other, as a user clicks through the tabs.
        for (const char *name : {"skyDock", "signalDock", "fixDock", "rtkDock", "infoDock",
                                 "satellitesDock", "attitudeDock", "consoleDock", "statsDock",
                                 "chartsDock", "deviationDock", "correctionsDock"}) {
            QDockWidget *d = dock(name);
            QVERIFY2(d, name);
            clickTabOf(*w_, d);
            QTRY_VERIFY2(d->widget()->isVisible(), name);
            QVERIFY2(!d->widget()->grab().isNull(), name); // paints
        }
        auto *sky = w_->findChild<ui::SkyPlotView *>("skyPlot");
        // The satellites are gathered afresh once the dialect is known (their numbering may
        // change with it): within two epochs of the receiver's identity.
        QTRY_VERIFY_WITH_TIMEOUT(sky->markers().size() >= 10, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(
                w_->findChild<ui::SignalLevelsView *>("signalLevels")->layoutBars().size() >= 10,
                5000);
        QTRY_VERIFY_WITH_TIMEOUT(labelText(w_.get(), "fixLatitude").contains("N"), 10000);
        QVERIFY(labelText(w_.get(), "fixSatellites").contains("/"));
        QTRY_VERIFY_WITH_TIMEOUT(labelText(w_.get(), "rtkRtcmTotal") != QStringLiteral("—"), 10000);
        // (The panel reads the model on its own timer: give it a moment on a busy machine.)
        QTRY_VERIFY2(labelText(w_.get(), "receiverIdentity").contains("NV08C"),
                     qPrintable(labelText(w_.get(), "receiverIdentity")));
        QVERIFY(w_->findChild<QAbstractItemView *>("satelliteTable")->model()->rowCount() >= 10);
        QVERIFY(w_->findChild<QAbstractItemView *>("consoleLines")->model()->rowCount() > 10);
        QTRY_VERIFY_WITH_TIMEOUT(
                w_->findChild<QWidget *>("messageStats")->findChild<QAbstractItemView *>() &&
                        w_->findChild<QWidget *>("messageStats")
                                        ->findChild<QAbstractItemView *>()
                                        ->model()
                                        ->rowCount() >= 5,
                5000);
        auto *charts = w_->findChild<ui::ChartsView *>();
        QVERIFY(charts);
        auto chartsHavePoints = [charts] {
            for (int s = 0; s < ui::TimeSeriesModel::SeriesCount; ++s)
                if (QLineSeries *line = charts->lineSeries(ui::TimeSeriesModel::Series(s));
                    line && line->count() > 0)
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(chartsHavePoints(), 5000);
        QVERIFY(w_->findChild<ui::DeviationView *>()->scatter().size() >= 3);
    }

    // A dock put away at first (the Base station), chosen in the View menu, is in front of its
    // tab group: not a new tab behind the one shown.
    void aDockChosenInTheViewMenuComesToTheFront() {
        QDockWidget *d = dock("baseDock");
        QVERIFY(d);
        QVERIFY(d->isHidden());
        d->toggleViewAction()->trigger();
        QTRY_VERIFY(d->widget()->isVisible());
        QVERIFY(!w_->tabifiedDockWidgets(d).isEmpty()); // it did join a tab group
        d->toggleViewAction()->trigger();
        QTRY_VERIFY(d->isHidden());
    }

    void tabTitlesAreWhole() {
        const QString cut = gnss::test::cutTabTitle(*w_);
        QVERIFY2(cut.isEmpty(), qPrintable(cut));
    }

    void theSettingsFormCanBeReadDockedAndFloated() {
        QDockWidget *d = dock("settingsDock");
        clickTabOf(*w_, d);
        auto *view = qobject_cast<ui::SettingsView *>(d->widget());
        QVERIFY(view);
        auto *engine = w_->findChild<config::SettingsEngine *>();
        QTRY_VERIFY_WITH_TIMEOUT(engine->receiverValue("rtk.ELGPS").has_value(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 20000);
        checkSettingsFormReadable(view, "docked");
        if (QTest::currentTestFailed()) return;
        // Floated: a window of its own at the size the dock had.
        const QSize docked = d->size();
        d->setFloating(true);
        d->resize(docked);
        QVERIFY(QTest::qWaitForWindowExposed(d));
        checkSettingsFormReadable(view, "floated");
        // Floated and made narrow: the groups become a combo box, rows wrap, nothing is cut.
        d->resize(420, 600);
        QTest::qWait(50);
        checkSettingsFormReadable(view, "floated narrow");
        d->setFloating(false);
    }

    // Types `value` into the form's editor for `key` and presses Apply, as a user does; returns
    // when the engine has finished (read-back included).
    void editAndApply(const std::string &key, const QString &value) {
        QDockWidget *d = dock("settingsDock");
        clickTabOf(*w_, d);
        auto *view = qobject_cast<ui::SettingsView *>(d->widget());
        auto *engine = w_->findChild<config::SettingsEngine *>();
        QTRY_VERIFY_WITH_TIMEOUT(!engine->isBusy(), 20000);
        ui::SettingEditor *editor = view->editor(key);
        QVERIFY2(editor, key.c_str());
        QWidget *input = editor->input();
        // Show its group, then type the new value.
        auto *list = view->findChild<QListWidget *>("settingGroups");
        auto *pages = view->findChild<QStackedWidget *>("settingPages");
        for (int i = 0; i < pages->count(); ++i)
            if (pages->widget(i)->isAncestorOf(editor)) {
                if (list->isVisible())
                    QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                                      list->visualItemRect(list->item(i)).center());
                else
                    view->findChild<QComboBox *>("settingGroupCombo")->setCurrentIndex(i);
            }
        qobject_cast<QScrollArea *>(pages->currentWidget())->ensureWidgetVisible(input);
        QTest::mouseClick(input, Qt::LeftButton);
        QTest::keyClick(input, Qt::Key_A, Qt::ControlModifier); // select all
        QTest::keyClicks(input, value);
        QTest::keyClick(input, Qt::Key_Tab);
        QVERIFY2(view->isEdited(key), "the form does not see the edit");
        auto *apply = view->findChild<QPushButton *>("settingsApply");
        QVERIFY(apply->isEnabled());
        QSignalSpy done(engine, &config::SettingsEngine::finished);
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(done.wait(20000));
        auto *outcomes = view->findChild<QTreeWidget *>("settingOutcomes");
        const QTreeWidgetItem *last = outcomes->topLevelItem(outcomes->topLevelItemCount() - 1);
        QVERIFY2(last->text(1) == QStringLiteral("done"), qPrintable(last->text(2)));
    }

    void anEditInTheFormReachesTheSimulator() {
        auto *engine = w_->findChild<config::SettingsEngine *>();
        QTRY_VERIFY_WITH_TIMEOUT(engine->receiverValue("rtk.ELGPS").has_value(), 20000);
        const std::string key = "rtk.ELGPS";
        const QString wanted = QString::fromStdString(*engine->receiverValue(key)) == "12"
                                       ? QStringLiteral("9")
                                       : QStringLiteral("12");
        editAndApply(key, wanted);
        if (QTest::currentTestFailed()) return;
        // Read back from the simulator: the receiver reports the new value.
        QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(*engine->receiverValue(key)), wanted,
                                  10000);
        auto *view = qobject_cast<ui::SettingsView *>(dock("settingsDock")->widget());
        QVERIFY(!view->isEdited(key));
        // The sky plot draws the receiver's new mask.
        QTRY_COMPARE(w_->findChild<ui::SkyPlotView *>("skyPlot")->elevationMask(),
                     wanted.toDouble());
    }

    void attitudeOutputSwitchedOnInTheFormFillsTheAttitudeDock() {
        // The default NV08C-RTK output has no attitude; the user adds PNVGIMU to the port's
        // output list in the form, and the attitude dock fills.
        editAndApply("output.COM1", "GGA:1;GSA:1;GSV:5;RMC:1;VTG:1;ZDA:5;PNVGBSS:5;PNVGIMU:1");
        if (QTest::currentTestFailed()) return;
        clickTabOf(*w_, dock("attitudeDock"));
        QTRY_VERIFY_WITH_TIMEOUT(labelText(w_.get(), "attitudeRoll") != QStringLiteral("—"), 10000);
        QVERIFY(labelText(w_.get(), "attitudeRoll").endsWith(QChar(0x00B0)));
    }

    void skyPlotLabelsDoNotCollide() {
        QDockWidget *d = dock("skyDock");
        clickTabOf(*w_, d);
        auto *sky = w_->findChild<ui::SkyPlotView *>("skyPlot");
        const auto ms = sky->markers();
        int labelled = 0;
        for (int i = 0; i < ms.size(); ++i) {
            if (ms[i].labelRect.isNull()) continue;
            ++labelled;
            QVERIFY(sky->rect().contains(ms[i].labelRect.toAlignedRect()));
            for (int j = 0; j < ms.size(); ++j) {
                if (j == i || ms[j].labelRect.isNull()) continue;
                QVERIFY2(!ms[i].labelRect.intersects(ms[j].labelRect),
                         qPrintable(ms[i].text + " / " + ms[j].text));
            }
        }
        QVERIFY2(labelled >= ms.size() * 3 / 4, qPrintable(QString::number(labelled)));
    }

    void aTcpSourceNobodyListensOnLeavesTheWindowResponsive() {
        QTcpServer probe;
        QVERIFY(probe.listen(QHostAddress::LocalHost));
        const QString where = QStringLiteral("127.0.0.1:%1").arg(probe.serverPort());
        probe.close();
        gnss::test::LoopWatch watch;
        w_->link()->connectTo(SourceSpec{SourceSpec::Kind::Tcp, where});
        QTRY_VERIFY_WITH_TIMEOUT(w_->link()->stateText().contains("trying again"), 5000);
        QTest::qWait(3000); // a few attempts, with growing waits
        QVERIFY2(watch.worst < 250, QByteArray::number(watch.worst));
        QVERIFY2(w_->link()->stateText().contains(where), qPrintable(w_->link()->stateText()));
        w_->link()->disconnectFromSource();
    }

    // A GeoS-5 sends only standard sentences until asked: the window asks each dialect's probe
    // (as gnss-cli probe does), speaks GeoStar from then on and shows the receiver's identity.
    void aReceiverWhoseOutputNamesNoVendorIsAsked() {
        link::test::SimProcess geostar(QStringList{"--dialect", "geostar", "--baud", "38400"});
        if (!geostar.ok()) QSKIP(qPrintable("gnss-sim: " + geostar.error));
        w_->link()->connectTo(SourceSpec{SourceSpec::Kind::Serial, geostar.device, 0});
        QTRY_VERIFY_WITH_TIMEOUT(w_->link()->state() == ReceiverLink::State::Connected, 30000);
        QTRY_COMPARE_WITH_TIMEOUT(QString::fromStdString(w_->stateModel()->state().identity.model),
                                  QString("GeoS-5M"), 20000);
        auto *c = w_->link()->connection();
        QVERIFY(c->stream()->dialect() && c->stream()->dialect()->id == "geostar");
        // GeoStar's own numbering (2.x: Galileo as 101-136 in GPGSV) from then on: no satellite
        // of unknown system, Galileo's among them.
        auto galileoAndNoUnknown = [this] {
            bool galileo = false;
            for (const auto &r : w_->satelliteModel()->rows()) {
                if (r.sat.system == gnss::Constellation::Unknown) return false;
                galileo |= r.sat.system == gnss::Constellation::Galileo;
            }
            return galileo;
        };
        // Within two epochs: the satellites numbered before the dialect was known are not kept
        // beside them as recently lost (for ten seconds, as a satellite that set is).
        QTRY_VERIFY_WITH_TIMEOUT(galileoAndNoUnknown(), 3000);
        w_->link()->disconnectFromSource();
    }

    void cleanupTestCase() {
        w_.reset();
        sim_.reset();
    }
};

QTEST_MAIN(TstWindowAcceptance)
#include "tst_window_acceptance.moc"
