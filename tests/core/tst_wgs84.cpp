// The one WGS-84 module: ECEF → latitude, longitude, ellipsoidal height against points whose ECEF
// coordinates were computed from their geodetic ones with 50-digit arithmetic (mpmath, the
// closed-form forward formula), and the other way round for the RTCM 1005 example's ARP; the
// forward formula against closed forms; round trips everywhere; metres per degree.
#include "core/wgs84.h"

#include <QTest>

#include <cmath>

using namespace gnss::wgs84;

namespace {
constexpr double kPolarRadius = 6356752.3142451794976; // WGS-84 semi-minor axis
constexpr double kDegTolerance = 1e-9;
constexpr double kHeightTolerance = 1e-3;
} // namespace

class TstWgs84 : public QObject {
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
        QTest::newRow("north pole") << 0.0 << 0.0 << kPolarRadius << 90.0 << 0.0 << 0.0;
        QTest::newRow("south pole, 100 m up")
                << 0.0 << 0.0 << -(kPolarRadius + 100) << -90.0 << 0.0 << 100.0;
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
        const auto g = toGeodetic({x, y, z});
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
                    const Ecef p = toEcef({lat, lon, h});
                    const auto g = toGeodetic(p);
                    QVERIFY(g.has_value());
                    QVERIFY(std::fabs(g->latDeg - lat) < kDegTolerance);
                    if (std::fabs(lat) < 90) QVERIFY(std::fabs(g->lonDeg - lon) < kDegTolerance);
                    QVERIFY(std::fabs(g->height - h) < kHeightTolerance);
                }
    }

    void knownPointsConvertToEcef_data() {
        QTest::addColumn<double>("latDeg");
        QTest::addColumn<double>("lonDeg");
        QTest::addColumn<double>("h");
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        // Equator / prime meridian and the pole: the ellipsoid's axes.
        QTest::newRow("equator") << 0.0 << 0.0 << 0.0 << 6378137.0 << 0.0 << 0.0;
        QTest::newRow("north pole") << 90.0 << 0.0 << 0.0 << 0.0 << 0.0 << 6356752.314245;
        QTest::newRow("equator 90E h=1000") << 0.0 << 90.0 << 1000.0 << 0.0 << 6379137.0 << 0.0;
        // Closed form at 45N 45E: x = y = N/2, z = N (1 - e^2) / sqrt(2).
        QTest::newRow("45N 45E") << 45.0 << 45.0 << 0.0 << 3194419.145061 << 3194419.145061
                                 << 4487348.408802;
        // Southern and western hemispheres (Santiago, 520 m), from an independent script of
        // the textbook formula.
        QTest::newRow("33.5S 70.25W 520m")
                << -33.5 << -70.25 << 520.0 << 1799238.6454 << -5011294.7024 << -3500621.2953;
    }
    void knownPointsConvertToEcef() {
        QFETCH(double, latDeg);
        QFETCH(double, lonDeg);
        QFETCH(double, h);
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        const Ecef e = toEcef({latDeg, lonDeg, h});
        QVERIFY2(std::fabs(e.x - x) < 0.01, qPrintable(QString::number(e.x, 'f', 4)));
        QVERIFY2(std::fabs(e.y - y) < 0.01, qPrintable(QString::number(e.y, 'f', 4)));
        QVERIFY2(std::fabs(e.z - z) < 0.01, qPrintable(QString::number(e.z, 'f', 4)));
    }

    void metresPerDegreeAreTheEllipsoidsRadii() {
        // At the equator: a degree of longitude is a * pi / 180, one of latitude b^2/a * pi/180.
        const auto eq = metresPerDegree(0);
        QVERIFY(std::fabs(eq.east - 111319.490793) < 1e-3);
        QVERIFY(std::fabs(eq.north - 110574.275821) < 1e-3);
        // A degree of longitude shrinks with the cosine of the latitude; none at the pole.
        QVERIFY(metresPerDegree(60).east < eq.east * 0.51);
        QVERIFY(std::fabs(metresPerDegree(90).east) < 1e-6);
        QVERIFY(metresPerDegree(60).north > eq.north);
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
        QVERIFY(!toGeodetic({x, y, z}).has_value());
    }
};

QTEST_GUILESS_MAIN(TstWgs84)
#include "tst_wgs84.moc"
