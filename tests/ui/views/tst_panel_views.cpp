// Fix panel, console, message statistics and receiver information, fed through the session.
#include "label_text.h"
#include "session_feed.h"
#include "views/console_view.h"
#include "views/fix_view.h"
#include "views/receiver_info_view.h"

#include <QComboBox>
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

class TstPanelViews : public QObject {
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
        QCOMPARE(label(view, "fixUtc"), QString("2018-05-31 15:35:56.000 UTC"));
        QCOMPARE(label(view, "fixCorrectionAge"), QString("0.6 s"));
        QCOMPARE(label(view, "fixBaseStation"), QString("100"));
        QCOMPARE(label(view, "fixSpeed"), QString("0.00 m/s (0.0 km/h)"));
    }

    // Preferences: the same epoch in every unit system, coordinate format and time zone.
    void fixPanelFollowsTheDisplayPreferences_data() {
        QTest::addColumn<int>("units");
        QTest::addColumn<int>("coordinates");
        QTest::addColumn<QString>("latitude");
        QTest::addColumn<QString>("altitude");
        QTest::addColumn<QString>("speed");
        using U = ui::UnitSystem;
        using C = ui::CoordinateFormat;
        // 10 kn = 5.144444 m/s = 11.51 mph; 192.245 m = 630.725 ft.
        QTest::newRow("metric, degrees") << int(U::Metric) << int(C::Degrees) << "55.84338247° N"
                                         << "192.245 m"
                                         << "5.14 m/s (18.5 km/h)";
        QTest::newRow("imperial, deg-min")
                << int(U::Imperial) << int(C::DegreesMinutes) << "55° 50.602948′ N"
                << "630.725 ft"
                << "11.51 mph";
        QTest::newRow("nautical, DMS")
                << int(U::Nautical) << int(C::DegreesMinutesSeconds) << "55° 50′ 36.1769″ N"
                << "192.245 m"
                << "10.00 kn";
    }
    void fixPanelFollowsTheDisplayPreferences() {
        QFETCH(int, units);
        QFETCH(int, coordinates);
        test::SessionFixture f;
        ui::FixView view(&f.state);
        f.feed({"$GPRMC,153556.00,A,5550.602948,N,03732.239612,E,010.00000,000.0,310518,,,R*4F",
                "$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,"
                "0100*46",
                "GPGGA,153557.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,0014.4,M,000.6,"
                "0100"}); // the next epoch closes this one
        ui::DisplayPrefs p;
        p.units = ui::UnitSystem(units);
        p.coordinates = ui::CoordinateFormat(coordinates);
        view.setDisplayPrefs(p);
        QTEST(label(view, "fixLatitude"), "latitude");
        QTEST(label(view, "fixAltMsl"), "altitude");
        QTEST(label(view, "fixSpeed"), "speed");
        // The view's own box shows the format in force; choosing there tells the window.
        auto *box = view.findChild<QComboBox *>("coordinateFormat");
        QCOMPARE(box->currentIndex(), coordinates);
        QSignalSpy chosen(&view, &ui::FixView::coordinateFormatChosen);
        box->setCurrentIndex(0);
        emit box->activated(0);
        QCOMPARE(chosen.size(), 1);
        QCOMPARE(label(view, "fixLatitude"), QString("55.84338247° N"));
    }

    void fixPanelShowsLocalTimeWithItsOffset() {
        qputenv("TZ", "Europe/Moscow"); // UTC+03:00 all year since 2014
        test::SessionFixture f;
        ui::FixView view(&f.state);
        f.feed({"$GPRMC,223556.00,A,5550.602948,N,03732.239612,E,000.00000,000.0,310518,,,R*4A",
                "GPRMC,223557.00,A,5550.602948,N,03732.239612,E,000.00000,000.0,310518,,,R"});
        ui::DisplayPrefs p;
        p.time = ui::TimeZoneChoice::Local;
        view.setDisplayPrefs(p);
        QCOMPARE(label(view, "fixUtc"), QString("2018-06-01 01:35:56.000 UTC+03:00"));
        p.time = ui::TimeZoneChoice::Utc;
        view.setDisplayPrefs(p);
        QCOMPARE(label(view, "fixUtc"), QString("2018-05-31 22:35:56.000 UTC"));
        qunsetenv("TZ");
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
        // A wrong checksum is refused, the right one named; nothing is sent.
        input->setText("$PNVGVER*00");
        QVERIFY(!view.submit());
        QVERIFY(spy.isEmpty());
        QVERIFY2(view.findChild<QLabel *>("consoleInputError")->text().contains("*4E"),
                 qPrintable(view.findChild<QLabel *>("consoleInputError")->text()));
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

QTEST_MAIN(TstPanelViews)
#include "tst_panel_views.moc"
