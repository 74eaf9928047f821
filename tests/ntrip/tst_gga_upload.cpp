// The GGA sent to casters: position in degrees and minutes in every quadrant, rounding that
// carries into the degree, UTC time of day, and a checksum that a plain XOR confirms.
#include "ntrip/gga_upload.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace gnss::ntrip;

namespace {

// The checksum recomputed independently: XOR of everything between '$' and '*'.
bool checksumIsRight(const std::string &s) {
    const auto star = s.find('*');
    if (s.empty() || s[0] != '$' || star == std::string::npos || star + 3 != s.size()) return false;
    unsigned x = 0;
    for (std::size_t i = 1; i < star; ++i) x ^= static_cast<unsigned char>(s[i]);
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02X", x);
    return s.substr(star + 1) == hex;
}

} // namespace

class TstGgaUpload : public QObject {
    Q_OBJECT
private slots:
    void ggaIsBuiltFromAPosition_data() {
        QTest::addColumn<double>("lat");
        QTest::addColumn<double>("lon");
        QTest::addColumn<double>("alt");
        QTest::addColumn<qint64>("ms");
        QTest::addColumn<QString>("expected"); // without the checksum
        QTest::newRow("Moscow at 10:00:00 UTC")
                << 55.7512 << 37.6184 << 152.0 << qint64(36000000)
                << "$GPGGA,100000.00,5545.07200,N,03737.10400,E,1,12,1.0,152.000,M,14.600,M,,";
        QTest::newRow("south and west, with hundredths of a second")
                << -33.8568 << -151.2153 << 5.5 << qint64(86399990)
                << "$GPGGA,235959.99,3351.40800,S,15112.91800,W,1,12,1.0,5.500,M,14.600,M,,";
        QTest::newRow("minutes that round up carry into the degree")
                << 10.9999999999 << -0.00000001 << 0.0 << qint64(0)
                << "$GPGGA,000000.00,1100.00000,N,00000.00000,W,1,12,1.0,0.000,M,14.600,M,,";
        QTest::newRow("time wraps at midnight and a longitude past 180 is folded")
                << 0.5 << 190.0 << -20.25 << qint64(86400000 + 61000)
                << "$GPGGA,000101.00,0030.00000,N,17000.00000,W,1,12,1.0,-20.250,M,14.600,M,,";
    }
    void ggaIsBuiltFromAPosition() {
        QFETCH(double, lat);
        QFETCH(double, lon);
        QFETCH(double, alt);
        QFETCH(qint64, ms);
        QFETCH(QString, expected);
        GgaPosition p;
        p.latDeg = lat;
        p.lonDeg = lon;
        p.altitudeMsl = alt;
        p.geoidSeparation = 14.6;
        const std::string gga = buildGga(p, ms);
        QVERIFY2(checksumIsRight(gga), gga.c_str());
        QCOMPARE(QString::fromStdString(gga.substr(0, gga.find('*'))), expected);
    }

    void qualitySatellitesAndHdopAreKeptInRange() {
        GgaPosition p;
        p.latDeg = 1;
        p.lonDeg = 1;
        p.quality = 4;
        p.satellites = 123;
        p.hdop = 0.74;
        const std::string gga = buildGga(p, 0);
        QVERIFY2(gga.find(",4,99,0.7,") != std::string::npos, gga.c_str());
        QVERIFY(checksumIsRight(gga));
    }

    void aPositionThatIsNotANumberSendsNoPosition() {
        GgaPosition p;
        p.latDeg = std::numeric_limits<double>::quiet_NaN();
        const std::string gga = buildGga(p, 1000);
        QVERIFY(checksumIsRight(gga));
        QCOMPARE(gga.substr(0, gga.find('*')), std::string("$GPGGA,000001.00,,,,,0,00,,,M,,M,,"));
    }
};

QTEST_APPLESS_MAIN(TstGgaUpload)
#include "tst_gga_upload.moc"
