// The GUI shell: menus present, start-up options parsed and refused as they should be.
#include "main_window.h"
#include "startup_options.h"

#include <QMenuBar>
#include <QTest>

using gnss::app::parseStartupOptions;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void mainWindowHasItsMenus() {
        gnss::app::MainWindow w;
        QStringList titles;
        for (QAction *a : w.menuBar()->actions()) titles << a->text().remove('&');
        QCOMPARE(titles, (QStringList{"File", "Receiver", "View", "Help"}));
    }

    void startupOptionsParse() {
        QString err;
        auto o = parseStartupOptions({"gnss-workbench", "--sim", "nvs", "--screenshot", "/tmp/x.png",
                                      "--quit-after", "2.5"},
                                     err);
        QVERIFY2(o, qPrintable(err));
        QCOMPARE(o->sim, QString("nvs"));
        QCOMPARE(o->quitAfter, 2.5);
        o = parseStartupOptions({"gnss-workbench", "--port", "/dev/ttyUSB0", "--baud", "115200"}, err);
        QVERIFY(o);
        QCOMPARE(o->baud, 115200);
    }

    void badStartupOptionsAreRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("unknown sim") << QStringList{"x", "--sim", "garmin"};
        QTest::newRow("two sources") << QStringList{"x", "--sim", "nvs", "--port", "/dev/ttyS0"};
        QTest::newRow("bad baud") << QStringList{"x", "--baud", "fast"};
        QTest::newRow("unknown option") << QStringList{"x", "--frobnicate"};
    }
    void badStartupOptionsAreRefused() {
        QFETCH(QStringList, args);
        QString err;
        QVERIFY(!parseStartupOptions(args, err));
        QVERIFY(!err.isEmpty());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
