// Coordinates as users type them (base/position_text.h): every form of an angle, hemispheres,
// and the refusals, each saying what was wrong.
#include "base/base_plan.h"
#include "base/position_text.h"

#include <QTest>

using namespace gnss;
using namespace gnss::base;

class TstPositionText : public QObject {
    Q_OBJECT
private slots:
    void angles_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("latitude");
        QTest::addColumn<double>("degrees");
        QTest::newRow("decimal") << "55.7512" << true << 55.7512;
        QTest::newRow("negative") << "-37.5" << false << -37.5;
        QTest::newRow("plus") << "+12.25" << false << 12.25;
        QTest::newRow("DM with space") << "55 45.072" << true << 55.7512;
        QTest::newRow("DM with marks") << "55°45.072'" << true << 55.7512;
        QTest::newRow("DMS marks") << "55°45'04.32\"" << true << 55.7512;
        QTest::newRow("DMS typographic") << "55°45′04.32″" << true << 55.7512;
        QTest::newRow("DMS colons") << "55:45:04.32" << true << 55.7512;
        QTest::newRow("DMS letters") << "55d45m4.32s" << true << 55.7512;
        QTest::newRow("hemisphere after") << "55 45.072 S" << true << -55.7512;
        QTest::newRow("hemisphere before") << "W37 37.104" << false << -37.6184;
        QTest::newRow("east") << "37.6184E" << false << 37.6184;
        QTest::newRow("pole") << "90" << true << 90.0;
        QTest::newRow("antimeridian") << "-180" << false << -180.0;
    }
    void angles() {
        QFETCH(QString, text);
        QFETCH(bool, latitude);
        QFETCH(double, degrees);
        std::string error;
        const auto a =
                parseAngle(text.toStdString(), latitude ? Axis::Latitude : Axis::Longitude, error);
        QVERIFY2(a, error.c_str());
        QVERIFY2(std::abs(*a - degrees) < 1e-9, qPrintable(QString::number(*a, 'f', 10)));
    }

    void refusals_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("latitude");
        QTest::addColumn<QString>("says");
        QTest::newRow("empty") << "" << true << "latitude: empty";
        QTest::newRow("beyond 90") << "91" << true << "beyond 90";
        QTest::newRow("beyond 180") << "180.5" << false << "beyond 180";
        QTest::newRow("minutes") << "55 61" << true << "minutes 61 are not below 60";
        QTest::newRow("seconds") << "55 1 60" << true << "seconds 60 are not below 60";
        QTest::newRow("decimals first") << "55.5 30" << true << "only the last";
        QTest::newRow("other axis") << "37E" << true << "other axis";
        QTest::newRow("sign and letter") << "-55N" << true << "a sign and a hemisphere";
        QTest::newRow("word") << "north" << true << "not an angle";
        QTest::newRow("four parts") << "1 2 3 4" << true << "expected degrees, minutes";
    }
    void refusals() {
        QFETCH(QString, text);
        QFETCH(bool, latitude);
        QFETCH(QString, says);
        std::string error;
        QVERIFY(!parseAngle(text.toStdString(), latitude ? Axis::Latitude : Axis::Longitude,
                            error));
        QVERIFY2(QString::fromStdString(error).contains(says), error.c_str());
    }

    void geodeticPoints() {
        std::string error;
        const auto g = parseGeodetic("55 45.072 N, 37°37'06.24\"E, 166.6", error);
        QVERIFY2(g, error.c_str());
        QVERIFY(std::abs(g->latDeg - 55.7512) < 1e-9 && std::abs(g->lonDeg - 37.6184) < 1e-9);
        QCOMPARE(g->height, 166.6);
        QVERIFY(!parseGeodetic("55.75,37.61", error));
        QVERIFY(QString::fromStdString(error).contains("LAT,LON,HEIGHT"));
        QVERIFY(!parseGeodetic("55.75,37.61,high", error));
        QVERIFY(QString::fromStdString(error).startsWith("height"));
    }

    void ecefPoints() {
        const auto p = ecefOf("2849848.385, 2196137.039,5249039.773");
        QVERIFY(p && p->x == 2849848.385 && p->z == 5249039.773);
        QVERIFY(nearTheEllipsoid(*p));
        QVERIFY(!ecefOf("1,2"));
        QVERIFY(!ecefOf("1,2,3,4"));
        QVERIFY(!ecefOf("1,x,3"));
        QVERIFY(!nearTheEllipsoid({2849.848, 2196.137, 5249.039})); // kilometres
        QCOMPARE(ecefText(*p), std::string("2849848.385,2196137.039,5249039.773"));
    }
};

QTEST_GUILESS_MAIN(TstPositionText)
#include "tst_position_text.moc"
