// WGS-84 conversion between ECEF X, Y, Z and latitude, longitude, ellipsoidal height, against
// known points and round trips.
#include "geodesy.h"

#include <QTest>

#include <cmath>

using namespace gnss::config;

class TstGeodesy : public QObject {
    Q_OBJECT
private slots:
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
        const Ecef e = toEcef({radians(latDeg), radians(lonDeg), h});
        QVERIFY2(std::fabs(e.x - x) < 0.01, qPrintable(QString::number(e.x, 'f', 4)));
        QVERIFY2(std::fabs(e.y - y) < 0.01, qPrintable(QString::number(e.y, 'f', 4)));
        QVERIFY2(std::fabs(e.z - z) < 0.01, qPrintable(QString::number(e.z, 'f', 4)));
        const Geodetic g = toGeodetic(e);
        QVERIFY(std::fabs(degrees(g.lat) - latDeg) < 1e-9);
        if (std::fabs(latDeg) < 89.9) QVERIFY(std::fabs(degrees(g.lon) - lonDeg) < 1e-9);
        QVERIFY(std::fabs(g.height - h) < 1e-4);
    }

    void roundTripsStayWithinATenthOfAMillimetre() {
        for (double lat = -89.5; lat <= 89.5; lat += 7.3)
            for (double lon = -179.0; lon <= 180.0; lon += 23.9)
                for (double h : {-400.0, 0.0, 150.0, 8848.0, 400000.0}) {
                    const Geodetic in{radians(lat), radians(lon), h};
                    const Geodetic out = toGeodetic(toEcef(in));
                    const Ecef a = toEcef(in), b = toEcef(out);
                    QVERIFY(std::hypot(a.x - b.x, a.y - b.y, a.z - b.z) < 1e-4);
                    QVERIFY(std::fabs(out.height - h) < 1e-4);
                }
    }
};

QTEST_APPLESS_MAIN(TstGeodesy)
#include "tst_geodesy.moc"
