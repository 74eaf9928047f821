// Great-circle distances against known figures, and the nearest mountpoint among RTCM 3
// streams (optionally only those taking GGA), skipping streams without a position.
#include "ntrip/mountpoint_distance.h"

#include <QTest>

using namespace gnss::ntrip;

class TstMountpointDistance : public QObject {
    Q_OBJECT
private slots:
    void distancesMatchKnownFigures_data() {
        QTest::addColumn<double>("lat1");
        QTest::addColumn<double>("lon1");
        QTest::addColumn<double>("lat2");
        QTest::addColumn<double>("lon2");
        QTest::addColumn<double>("km");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("the same point") << 55.75 << 37.62 << 55.75 << 37.62 << 0.0 << 1e-9;
        QTest::newRow("one degree of latitude") << 0.0 << 0.0 << 1.0 << 0.0 << 111.195 << 0.001;
        QTest::newRow("Moscow to Saint Petersburg")
                << 55.7558 << 37.6173 << 59.9343 << 30.3351 << 634.4 << 2.0;
        QTest::newRow("across the antimeridian")
                << 0.0 << 179.5 << 0.0 << -179.5 << 111.195 << 0.001;
        QTest::newRow("antipodes") << 10.0 << 20.0 << -10.0 << -160.0 << 20015.1 << 0.1;
    }
    void distancesMatchKnownFigures() {
        QFETCH(double, lat1);
        QFETCH(double, lon1);
        QFETCH(double, lat2);
        QFETCH(double, lon2);
        QFETCH(double, km);
        QFETCH(double, tolerance);
        const double d = greatCircleMetres(lat1, lon1, lat2, lon2) / 1000.0;
        QVERIFY2(std::fabs(d - km) <= tolerance, qPrintable(QString::number(d, 'f', 4)));
        QCOMPARE(greatCircleMetres(lat2, lon2, lat1, lon1) / 1000.0, d);
    }

    void theNearestQualifyingMountpointIsChosen_data() {
        QTest::addColumn<bool>("rtcm3Only");
        QTest::addColumn<bool>("onlyGga");
        QTest::addColumn<QString>("expected");
        QTest::newRow("RTCM 3 only: the CMR stream next door is passed over")
                << true << false << "NEAR_RTCM3";
        QTest::newRow("any format: the CMR stream wins") << false << false << "CMR_NEXT_DOOR";
        QTest::newRow("only streams taking GGA") << true << true << "FAR_VRS";
    }
    void theNearestQualifyingMountpointIsChosen() {
        QFETCH(bool, rtcm3Only);
        QFETCH(bool, onlyGga);
        QFETCH(QString, expected);
        const SourceTable t = parseSourceTable(
                "STR;UNLOCATED;x;RTCM 3.2;;2;GPS;N;RUS;0.00;0.00;0;0;g;none;B;N;9600;\r\n"
                "STR;NOPOS;x;RTCM 3.2;;2;GPS;N;RUS;;;0;0;g;none;B;N;9600;\r\n"
                "STR;CMR_NEXT_DOOR;x;CMR+;;2;GPS;N;RUS;55.76;37.62;0;0;g;none;B;N;9600;\r\n"
                "STR;NEAR_RTCM3;x;RTCM 3.3;;2;GPS;N;RUS;55.90;37.50;0;0;g;none;B;N;9600;\r\n"
                "STR;FAR_VRS;x;RTCM 3;;2;GPS;N;RUS;59.90;30.30;1;1;g;none;B;N;9600;\r\n"
                "STR;FARTHER;x;RTCM 3;;2;GPS;N;RUS;43.10;131.90;0;0;g;none;B;N;9600;\r\n");
        NearestOptions o;
        o.rtcm3Only = rtcm3Only;
        o.onlyWantingGga = onlyGga;
        const NearestChoice c = nearestMountpoint(t, 55.7512, 37.6184, o);
        QVERIFY(c.entry);
        QCOMPARE(QString::fromStdString(c.entry->mountpoint), expected);
        QCOMPARE(c.distanceMetres,
                 greatCircleMetres(55.7512, 37.6184, *c.entry->latitude, *c.entry->longitude));
    }

    void noQualifyingStreamGivesNoChoice() {
        const SourceTable t =
                parseSourceTable("STR;A;x;RTCM 2.3;;2;GPS;N;RUS;55;37;0;0;g;none;B;N;9600;\r\n");
        QVERIFY(!nearestMountpoint(t, 55, 37).entry);
        QVERIFY(!nearestMountpoint(SourceTable{}, 55, 37).entry);
        QVERIFY(!nearestMountpoint(t, std::nan(""), 37, {false, false}).entry);
    }
};

QTEST_APPLESS_MAIN(TstMountpointDistance)
#include "tst_mountpoint_distance.moc"
