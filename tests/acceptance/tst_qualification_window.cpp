// The Qualification dock in the real window at 1280x800: an NV08C-RTK and a VT002 simulated on
// pseudo-terminals (baud "auto", the real QSerialPort), each told its cold-start times (40 s
// ± 4 simulated, at --speed 20: 2 s on the host's clock). A hot start asked of both is refused
// before anything is sent, naming the receiver without one; three cold starts on both at once
// fill the table (one row per receiver, medians within 25 % of 2 s), the limits' pass and FAIL,
// the CDF with a series per receiver, every run, and the accuracy against a typed point; the
// report written from it reads back with pdftotext (identity and the TTFF table).
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "cli_run.h"
#include "common/app_transports.h"
#include "gui/main_window.h"
#include "gui/qualification_controller.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "qualify/accuracy_panel.h"
#include "qualify/qualification_view.h"
#include "qualify/qualify_plots.h"
#include "session/receiver_link.h"
#include "sim_process.h"
#include "sites/site_store.h"
#include "window_children.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss;
using gnss::link::SourceSpec;
using gnss::link::test::SimProcess;
using gnss::session::ReceiverLink;

namespace {

using gnss::test::child;
constexpr auto connected = gnss::test::connectedWithEpochs;

} // namespace

class TstQualificationWindow : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();
    link::TransportFactory transports_ = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QTemporaryDir dir_;

private slots:
    void aShortCampaignOnTwoReceivers() {
        const QStringList told = {"--speed", "20", "--ttff", "cold=40:4"};
        SimProcess nvs(QStringList{"--dialect", "nvs", "--baud", "38400"} + told);
        SimProcess vt(QStringList{"--dialect", "nemerix"} + told);
        REQUIRE_SIM(nvs);
        REQUIRE_SIM(vt);
        QSettings settings(dir_.filePath("window.ini"), QSettings::IniFormat);
        // The site list in a folder of the test's own (shared with gnss-cli through the same
        // variable).
        qputenv(sites::SiteStore::kDirectoryVariable, dir_.filePath("data").toUtf8());
        app::MainWindow w(registry_, transports_, &settings);
        w.resize(1280, 800);
        w.show();
        QVERIFY(w.showDock("qualify"));
        w.connectReceiversAtStart({{SourceSpec::Kind::Serial, nvs.device, 0},
                                   {SourceSpec::Kind::Serial, vt.device, 0}});
        QCOMPARE(w.sessions().size(), 2);
        ui::ReceiverSession *a = w.sessions()[0], *b = w.sessions()[1];
        QTRY_VERIFY_WITH_TIMEOUT(connected(a) && connected(b), 40000);
        QTRY_VERIFY_WITH_TIMEOUT(a->dialect() && b->dialect(), 15000);

        auto *view = w.dock("qualifyDock")->findChild<ui::QualificationView *>();
        QVERIFY(view && view->isVisible());
        auto *scope = child<QComboBox>(view, "qualifyScope");
        QTRY_VERIFY(scope->isEnabled()); // two receivers: "every receiver" offered
        scope->setCurrentIndex(1);
        child<QSpinBox>(view, "qualifyRuns")->setValue(3);
        child<QSpinBox>(view, "qualifyPause")->setValue(0);
        child<QSpinBox>(view, "qualifyTimeout")->setValue(30);
        child<QLineEdit>(view, "qualifyLimits")->setText("cold:mean<=60, cold:max<=1");
        view->accuracy()->setReferenceText("55.7512,37.6184,167.1");

        // A hot start of both: the NV08C-RTK has none; refused, nothing written to either.
        child<QCheckBox>(view, "qualifyCold")->setChecked(false);
        child<QCheckBox>(view, "qualifyHot")->setChecked(true);
        // (The watch below sees every restart written from here on; none may be yet.)
        QElapsedTimer clock;
        clock.start();
        QList<qint64> restartsA, restartsB;
        auto watch = [&clock](ui::ReceiverSession *s, QList<qint64> &times) {
            QObject::connect(s->link()->connection()->commands(), &link::CommandQueue::commandSent,
                             s, [&clock, &times](int, const QString &text, int) {
                                 if (text.contains("PNVGRST") || text.contains("PNMRX111"))
                                     times << clock.elapsed();
                             });
        };
        watch(a, restartsA);
        watch(b, restartsB);
        QTest::mouseClick(child<QPushButton>(view, "qualifyStart"), Qt::LeftButton);
        QVERIFY2(view->message().contains("no hot start"), qPrintable(view->message()));
        QVERIFY(view->message().contains(a->name()));
        QVERIFY(!w.qualification()->running());
        QTest::qWait(300);
        QVERIFY(restartsA.isEmpty() && restartsB.isEmpty());

        // Three cold starts on both at once: each restart written to both at the same moment.
        child<QCheckBox>(view, "qualifyHot")->setChecked(false);
        child<QCheckBox>(view, "qualifyCold")->setChecked(true);
        QTest::mouseClick(child<QPushButton>(view, "qualifyStart"), Qt::LeftButton);
        QVERIFY2(view->message().isEmpty(), qPrintable(view->message()));
        QVERIFY(w.qualification()->running());
        QVERIFY(!child<QPushButton>(view, "qualifyStart")->isEnabled());
        QVERIFY(child<QPushButton>(view, "qualifyCancel")->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!w.qualification()->running(), 90000);
        QCOMPARE(restartsA.size(), 3);
        QCOMPARE(restartsB.size(), 3);
        for (int i = 0; i < 3; ++i)
            QVERIFY2(std::abs(restartsA[i] - restartsB[i]) < 250,
                     qPrintable(QString("restart %1: %2 and %3 ms")
                                        .arg(i)
                                        .arg(restartsA[i])
                                        .arg(restartsB[i])));

        QTableWidget *results = view->resultsTable();
        QCOMPARE(results->rowCount(), 2);
        for (int r = 0; r < 2; ++r) {
            QCOMPARE(results->item(r, 2)->text(), QString("3")); // runs
            QCOMPARE(results->item(r, 3)->text(), QString("3")); // fixed
            const double median = results->item(r, 7)->text().toDouble();
            QVERIFY2(std::abs(median - 2.0) < 0.5,
                     qPrintable(results->item(r, 0)->text() + ": " + results->item(r, 7)->text()));
            const QString limits = results->item(r, 12)->text();
            QVERIFY2(limits.contains("pass") && limits.contains("FAIL"), qPrintable(limits));
        }
        QCOMPARE(results->item(0, 0)->text(), a->name());
        QCOMPARE(results->item(1, 0)->text(), b->name());
        QCOMPARE(view->runsTable()->rowCount(), 6);
        QCOMPARE(view->cdf()->series().size(), std::size_t(2));
        QCOMPARE(view->cdf()->series()[0].seconds.size(), std::size_t(3));

        // The CDF and the accuracy, shown at laptop size.
        view->tabs()->setCurrentWidget(view->cdf());
        QTRY_VERIFY(view->cdf()->isVisible() && view->cdf()->height() >= 80);
        view->tabs()->setCurrentWidget(view->accuracy());
        w.selectReceiver(a);
        QTRY_VERIFY_WITH_TIMEOUT(!view->accuracy()->valueOf("CEP50").isEmpty(), 5000);
        QVERIFY(!view->accuracy()->valueOf("Bias east").isEmpty());
        QVERIFY(view->accuracy()->histogram()->count() > 0);

        // The mean kept as a site (a survey-in by the workbench), seen by gnss-cli, and used
        // back as the reference.
        QString why;
        QVERIFY2(view->accuracy()->saveMeanAsSite("Bench roof", &why), qPrintable(why));
        QVERIFY(!view->accuracy()->saveMeanAsSite("bench ROOF", &why)); // taken
        QVERIFY(why.contains("already"));
        const auto listed = test::runCli({"sites", "list", "--json"});
        QVERIFY2(listed.exitCode == 0 && listed.out.contains("Bench roof") &&
                         listed.out.contains("survey-in"),
                 listed.out + listed.err);
        view->accuracy()->setReferenceText({});
        QVERIFY(view->accuracy()->useSite("Bench roof", &why));
        QVERIFY(view->accuracy()->referenceText().startsWith("55.75"));
        QTRY_VERIFY(view->accuracy()->valueOf("Positions").contains("against the reference"));
        const QString shot = qEnvironmentVariable("GNSS_TEST_SHOTS", dir_.path());
        QVERIFY(w.grab().save(shot + "/qualification.png"));

        // The report, read back.
        QString error;
        const QStringList files = w.qualification()->writeReport(dir_.filePath("q.pdf"), &error);
        QVERIFY2(files.size() == 3, qPrintable(error));
        const QString pdftotext = QStandardPaths::findExecutable("pdftotext");
        if (pdftotext.isEmpty()) QSKIP("pdftotext (poppler-utils) is not installed");
        QProcess p;
        p.start(pdftotext, {"-layout", dir_.filePath("q.pdf"), "-"});
        QVERIFY(p.waitForFinished(20000));
        const QString text = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(text.contains("NV08C") && text.contains("VT002"), qPrintable(text.left(2000)));
        QVERIFY(text.contains(nvs.device));
        QVERIFY(text.contains("Median"));

        // Cancelled at once: it ends, the runs so far kept, Start offered again.
        QTest::mouseClick(child<QPushButton>(view, "qualifyStart"), Qt::LeftButton);
        QVERIFY(w.qualification()->running());
        QTest::mouseClick(child<QPushButton>(view, "qualifyCancel"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w.qualification()->running(), 5000);
        QVERIFY(child<QPushButton>(view, "qualifyStart")->isEnabled());
        QVERIFY(!child<QPushButton>(view, "qualifyCancel")->isEnabled());
    }
};

QTEST_MAIN(TstQualificationWindow)
#include "tst_qualification_window.moc"
