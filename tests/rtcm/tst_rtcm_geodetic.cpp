// ECEF → WGS-84 latitude, longitude, ellipsoidal height, against points whose ECEF coordinates
// were computed from their geodetic ones with 50-digit arithmetic (mpmath, the closed-form
// forward formula), and the other way round for the 1005 example's ARP.
#include "rtcm/geodetic.h"

#include <QTest>

#include <cmath>

using namespace gnss::rtcm;

namespace {
constexpr double kB = 6356752.3142451794976; // WGS-84 semi-minor axis
constexpr double kDegTolerance = 1e-9;
constexpr double kHeightTolerance = 1e-3;
} // namespace

class TestRtcmGeodetic : public QObject {
    Q_OBJECT
private slots:
    void ecefToGeodeticMatchesKnownPoints_data() {
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        QTest::addColumn<double>("lat");
        QTest::addColumn<double>("lon");
        QTest::addColumn<double>("h");
        QTest::newRow("equator, prime meridian") << 6378137.0 << 0.0 << 0.0 << 0.0 << 0.0 << 0.0;
        QTest::newRow("equator, 90 E") << 0.0 << 6378137.0 << 0.0 << 0.0 << 90.0 << 0.0;
        QTest::newRow("equator, 180, 1 km up")
                << -6379137.0 << 0.0 << 0.0 << 0.0 << 180.0 << 1000.0;
        QTest::newRow("north pole") << 0.0 << 0.0 << kB << 90.0 << 0.0 << 0.0;
        QTest::newRow("south pole, 100 m up") << 0.0 << 0.0 << -(kB + 100) << -90.0 << 0.0 << 100.0;
        QTest::newRow("Moscow 55.75222 N 37.61556 E 156 m")
                << 2849878.1520592680882 << 2195934.8380679322578 << 5249094.9247639375534
                << 55.75222 << 37.61556 << 156.0;
        QTest::newRow("Sydney 33.8688 S 151.2093 E 58.25 m")
                << -4646093.6592073695852 << 2553229.6357894757601 << -3534404.8502336315207
                << -33.8688 << 151.2093 << 58.25;
        QTest::newRow("geostationary height 10 N 120 W")
                << -20762101.539449165505 << -35961014.738229957581 << 7314422.233724131019 << 10.0
                << -120.0 << 35786000.0;
        QTest::newRow("5 km below the ellipsoid 45 S 60 W")
                << 2257027.6724714991449 << -3909286.6028095635721 << -4483812.8749599870793
                << -45.0 << -60.0 << -5000.0;
        // Inverse computed by iterating the exact relation to convergence at 50 digits.
        QTest::newRow("RTCM 10403 1005 example ARP")
                << 1114104.5999 << -4850729.7108 << 3975521.4643 << 38.804759430425067869
                << -77.064773599803475551 << 114.56113815521872257;
    }
    void ecefToGeodeticMatchesKnownPoints() {
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        QFETCH(double, lat);
        QFETCH(double, lon);
        QFETCH(double, h);
        const auto g = ecefToGeodetic({x, y, z});
        QVERIFY(g.has_value());
        QVERIFY2(std::fabs(g->latDeg - lat) < kDegTolerance,
                 qPrintable(QString::number(g->latDeg, 'g', 17)));
        QVERIFY2(std::fabs(g->lonDeg - lon) < kDegTolerance,
                 qPrintable(QString::number(g->lonDeg, 'g', 17)));
        QVERIFY2(std::fabs(g->height - h) < kHeightTolerance,
                 qPrintable(QString::number(g->height, 'g', 17)));
    }

    void geodeticToEcefAndBackAgreeEverywhere() {
        for (double lat = -90; lat <= 90; lat += 7.5)
            for (double lon = -180; lon < 180; lon += 15)
                for (const double h : {-500.0, 0.0, 1234.5, 400e3, 20200e3}) {
                    const Ecef p = geodeticToEcef({lat, lon, h});
                    const auto g = ecefToGeodetic(p);
                    QVERIFY(g.has_value());
                    QVERIFY(std::fabs(g->latDeg - lat) < kDegTolerance);
                    if (std::fabs(lat) < 90) QVERIFY(std::fabs(g->lonDeg - lon) < kDegTolerance);
                    QVERIFY(std::fabs(g->height - h) < kHeightTolerance);
                }
    }

    void pointsWithoutALatitudeHaveNoPosition_data() {
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        QTest::newRow("the centre") << 0.0 << 0.0 << 0.0;
        QTest::newRow("half a metre from the centre") << 0.5 << 0.0 << 0.0;
        QTest::newRow("not a number") << std::nan("") << 1.0 << 1.0;
        QTest::newRow("infinite") << HUGE_VAL << 1.0 << 1.0;
    }
    void pointsWithoutALatitudeHaveNoPosition() {
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        QVERIFY(!ecefToGeodetic({x, y, z}).has_value());
    }
};

QTEST_GUILESS_MAIN(TestRtcmGeodetic)
#include "tst_rtcm_geodetic.moc"
