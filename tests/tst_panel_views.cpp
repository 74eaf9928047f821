// Fix panel, console, message statistics and receiver information, fed through the session.
#include "label_text.h"
#include "session_feed.h"
#include "views/console_view.h"
#include "views/fix_view.h"
#include "views/receiver_info_view.h"

#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

using namespace gnss;

namespace {
QString label(QWidget &w, const char *name) {
    return test::labelText(w, name);
}
} // namespace

class TestPanelViews : public QObject {
    Q_OBJECT
private slots:
    void fixPanelShowsTheEpoch() {
        test::SessionFixture f;
        ui::FixView view(&f.state);
        QCOMPARE(label(view, "fixLatitude"), QString("—"));
        f.feed({"$GPRMC,153556.00,A,5550.602948,N,03732.239612,E,000.00000,000.0,310518,,,R*4E",
                "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,"
                "0100*46",
                "$GPGSA,A,3,001,010,011,012,013,015,017,018,019,024,028,030,1.0,0.5,0.8*33",
                "GPGGA,153557.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,"
                "0100"});
        view.refresh();
        QCOMPARE(label(view, "fixBadge"), QString("RTK fixed"));
        QCOMPARE(label(view, "fixLatitude"), QString("55.84338247° N"));
        QCOMPARE(label(view, "fixLongitude"), QString("37.53732687° E"));
        QCOMPARE(label(view, "fixAltMsl"), QString("192.245 m"));
        QCOMPARE(label(view, "fixAltEllipsoid"), QString("206.645 m"));
        QCOMPARE(label(view, "fixDops"), QString("1.00 / 0.70 / 0.80")); // HDOP from GGA
        QCOMPARE(label(view, "fixUtc"), QString("2018-05-31 15:35:56.000"));
        QCOMPARE(label(view, "fixCorrectionAge"), QString("0.6 s"));
        QCOMPARE(label(view, "fixBaseStation"), QString("100"));
        QVERIFY(label(view, "fixSpeed").startsWith("0.00 m/s"));
        view.setDegreesMinutesSeconds(true);
        QCOMPARE(label(view, "fixLatitude"), QString("55° 50′ 36.1769″ N"));
    }

    void consoleShowsLinesMarksErrorsAndFilters() {
        test::SessionFixture f;
        ui::ConsoleView view(&f.console);
        f.feed({"$GPGGA,000008.00,,,,,0,,,,,,,,,*40", "GPGSV,1,1,00", "PNVGVER"});
        f.session.noteSent("$PNVGVER*4E");
        f.session.refresh();
        QCOMPARE(f.console.rowCount(), 4);
        QVERIFY(f.console.data(f.console.index(0), ui::ConsoleModel::ChecksumBadRole).toBool());
        QVERIFY(f.console.data(f.console.index(3), ui::ConsoleModel::SentRole).toBool());
        view.setFilter("GSV");
        QCOMPARE(view.visibleLines(), 1);
        view.setFilter("");
        QCOMPARE(view.visibleLines(), 4);
    }

    void consoleSendAddsTheChecksumAndRefusesMalformedInput() {
        test::SessionFixture f;
        ui::ConsoleView view(&f.console);
        view.setCommandNames({"PNVGVER", "PNVGRTK"});
        QSignalSpy spy(&view, &ui::ConsoleView::sendRequested);
        auto *input = view.findChild<QLineEdit *>("consoleInput");
        input->setText("PNVGVER");
        QVERIFY(view.submit());
        QCOMPARE(spy.takeFirst().at(0).toByteArray(), QByteArray("$PNVGVER*4E"));
        input->setText("$PNVG\tBAD");
        QVERIFY(!view.submit());
        QVERIFY(spy.isEmpty());
        QVERIFY(!view.findChild<QLabel *>("consoleInputError")->text().isEmpty());
        QCOMPARE(view.history(), QStringList{"PNVGVER"});
    }

    void messageStatisticsCountRatesAndErrors() {
        test::SessionFixture f;
        f.feed({"GPGGA,120000,,,,,0,,,,,,,,", "GPGGA,120001,,,,,0,,,,,,,,",
                "$GPGGA,000008.00,,,,,0,,,,,,,,,*40"});
        QCOMPARE(f.messages.rowCount(), 1);
        const auto &row = f.messages.rows().front();
        QCOMPARE(row.address, QString("GPGGA"));
        QCOMPARE(row.count, quint64(3));
        QCOMPARE(row.checksumErrors, quint64(1));
        f.messages.refresh({{"GPGGA", 13}}, row.history.front().first + 1000);
        QVERIFY(std::abs(f.messages.rows().front().rateHz - 10.0) < 0.01);
    }

    void receiverInformationShowsIdentityReportsAndJamming() {
        test::SessionFixture f;
        ui::ReceiverInfoView view(&f.state);
        f.feed({"$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C",
                "GPGGA,120000,,,,,0,,,,,,,,", "GPGGA,120001,,,,,0,,,,,,,,"});
        view.refresh();
        QVERIFY(label(view, "receiverIdentity").contains("GeoS-5M"));
        QVERIFY(label(view, "receiverIdentity").contains("5.102"));
        QCOMPARE(label(view, "jammingIndicator"), QString("Jamming: none detected"));
        QTreeWidget *tree = view.tree();
        QCOMPARE(tree->topLevelItemCount(), 1);
        const auto found = tree->findItems("Antenna", Qt::MatchRecursive | Qt::MatchContains);
        QVERIFY(!found.isEmpty());
    }
};

QTEST_MAIN(TestPanelViews)
#include "tst_panel_views.moc"
