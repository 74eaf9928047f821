// Accuracy against a known point: the reference parsed (or refused with the reason), each epoch's
// error east/north/up, the bias, the horizontal and vertical spreads, CEP about the mean, R95,
// 2DRMS and the shares within each distance, overall and per fix type; epochs without a fix or a
// position are left out, and heights count only above the ellipsoid.
#include "compare/accuracy.h"
#include "core/json_writer.h"
#include "core/wgs84.h"
#include "state/epoch.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace gnss;
using namespace gnss::compare;

namespace {

const ReferencePoint kPoint{55.7512, 37.6184, 166.6};

// An epoch `east`, `north` metres from the point and `up` above it, its height given as sea
// level plus a geoid separation (as GGA gives it), or sea level alone when `geoid` is false.
Epoch at(double east, double north, double up, FixType fix = FixType::RtkFixed, bool geoid = true) {
    const auto m = wgs84::metresPerDegree(kPoint.latDeg);
    Epoch e;
    e.fix = fix;
    e.lat = kPoint.latDeg + north / m.north;
    e.lon = kPoint.lonDeg + east / m.east;
    e.geoidSep = geoid ? std::optional(14.0) : std::nullopt;
    e.altMsl = *kPoint.height + up - (geoid ? 14.0 : 0.0);
    return e;
}

} // namespace

class TstAccuracy : public QObject {
    Q_OBJECT
private slots:
    void referencesParse_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("lat,lon") << "55.7512,37.6184" << true << "";
        QTest::newRow("lat,lon,height") << "-33.9,18.4,12.5" << true << "";
        QTest::newRow("spaces") << " 55.75 , 37.61 , 150 " << true << "";
        QTest::newRow("one number") << "55.75" << false << "LAT,LON";
        QTest::newRow("four numbers") << "1,2,3,4" << false << "LAT,LON";
        QTest::newRow("latitude past the pole") << "91,0" << false << "latitude";
        QTest::newRow("longitude past 180") << "0,181" << false << "longitude";
        QTest::newRow("not a number") << "north,0" << false << "latitude";
        QTest::newRow("bad height") << "0,0,high" << false << "height";
        QTest::newRow("empty") << "" << false << "LAT,LON";
    }
    void referencesParse() {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(QString, mentions);
        std::string why;
        const auto p = ReferencePoint::parse(text.toStdString(), why);
        QCOMPARE(p.has_value(), ok);
        if (!ok) QVERIFY2(QString::fromStdString(why).contains(mentions), why.c_str());
    }

    void aKnownOffsetComesBack() {
        Accuracy a(kPoint);
        for (int i = 0; i < 100; ++i) QVERIFY(a.add(at(0.3, -0.2, 0.5)));
        const AccuracyReport r = a.report();
        QCOMPARE(r.positions, std::size_t(100));
        QCOMPARE(r.heights, std::size_t(100));
        QVERIFY2(std::abs(r.biasEast - 0.3) < 1e-3, QByteArray::number(r.biasEast));
        QVERIFY2(std::abs(r.biasNorth + 0.2) < 1e-3, QByteArray::number(r.biasNorth));
        QVERIFY(r.biasUp && std::abs(*r.biasUp - 0.5) < 1e-3);
        const double d = std::hypot(0.3, 0.2);
        QVERIFY(std::abs(r.horizontal.mean - d) < 1e-3);
        QVERIFY(std::abs(r.horizontal.p95 - d) < 1e-3); // R95
        QVERIFY(std::abs(r.drms2 - 2 * d) < 2e-3);
        QVERIFY(r.cep50 < 1e-3 && r.cep95 < 1e-3); // no spread about the mean: all bias
        QVERIFY(std::abs(r.vertical.p95 - 0.5) < 1e-3);
        QCOMPARE(r.within.percent[0], 0.0);   // 2 cm
        QCOMPARE(r.within.percent[1], 0.0);   // 10 cm
        QCOMPARE(r.within.percent[2], 100.0); // 50 cm
    }

    // Shares within each distance, overall and per fix type; CEP about the mean position.
    void sharesAndSpread() {
        Accuracy a(kPoint);
        for (int i = 0; i < 50; ++i) a.add(at(0.01, 0, 0, FixType::RtkFixed)); // 1 cm
        for (int i = 0; i < 30; ++i) a.add(at(0, 0.3, 0, FixType::RtkFloat));  // 30 cm
        for (int i = 0; i < 20; ++i) a.add(at(-3, 0, 0, FixType::Fix3D));      // 3 m
        a.add(at(100, 0, 0, FixType::None));                                   // no fix: left out
        Epoch noPosition;
        noPosition.fix = FixType::Fix3D;
        QVERIFY(!a.add(noPosition));
        const AccuracyReport r = a.report();
        QCOMPARE(r.positions, std::size_t(100));
        const std::array<double, 6> want{50, 50, 80, 80, 80, 100};
        for (std::size_t k = 0; k < want.size(); ++k)
            QVERIFY2(
                    std::abs(r.within.percent[k] - want[k]) < 1e-9,
                    qPrintable(QString("%1 m: %2").arg(kWithinMetres[k]).arg(r.within.percent[k])));
        QCOMPARE(r.withinByFix.at(FixType::RtkFixed).percent[0], 100.0);
        QCOMPARE(r.withinByFix.at(FixType::RtkFloat).percent[1], 0.0);
        QCOMPARE(r.withinByFix.at(FixType::RtkFloat).percent[2], 100.0);
        QCOMPARE(r.withinByFix.at(FixType::Fix3D).percent[4], 0.0);
        QCOMPARE(r.withinByFix.count(FixType::None), std::size_t(0));
        QVERIFY(std::abs(r.horizontal.median - 0.155) < 2e-3); // between ranks 50 and 51
        QVERIFY(std::abs(r.horizontal.max - 3) < 2e-3);
        // The mean is 0.595 m west: CEP about it differs from the distances about the point.
        QVERIFY(std::abs(r.biasEast - (0.5 - 60) / 100) < 2e-3);
        QVERIFY(r.cep50 > 0.5 && r.cep50 < 0.7);
    }

    // A receiver without a geoid separation gives heights above the sea: no vertical error.
    void seaLevelHeightsAreNotCompared() {
        Accuracy a(kPoint);
        for (int i = 0; i < 10; ++i) a.add(at(1, 0, 0, FixType::Fix3D, false));
        const AccuracyReport r = a.report();
        QCOMPARE(r.heights, std::size_t(0));
        QVERIFY(!r.biasUp);
        QVERIFY(std::abs(r.biasEast - 1) < 1e-3);
        // A point without a height: horizontal only, whatever the receiver gives.
        Accuracy flat({kPoint.latDeg, kPoint.lonDeg, std::nullopt});
        flat.add(at(0, 2, 5));
        QVERIFY(!flat.report().biasUp);
        QVERIFY(std::abs(flat.report().biasNorth - 2) < 1e-3);
    }

    void jsonHasTheIssuesKeys() {
        Accuracy a(kPoint);
        for (int i = 0; i < 10; ++i) a.add(at(0.3, -0.2, 0.5));
        std::string out;
        JsonWriter w(out);
        a.report().writeJson(w, kPoint);
        const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(out)).object();
        QVERIFY2(!o.isEmpty(), out.c_str());
        QVERIFY(std::abs(o["bias_m"].toObject()["east"].toDouble() - 0.3) < 1e-3);
        QVERIFY(std::abs(o["bias_m"].toObject()["up"].toDouble() - 0.5) < 1e-3);
        for (const char *k : {"mean", "median", "cep50", "cep95", "drms2", "r95"})
            QVERIFY2(o["horizontal_m"].toObject().contains(k), k);
        for (const char *k : {"mean", "median", "p95"})
            QVERIFY2(o["vertical_m"].toObject().contains(k), k);
        QCOMPARE(o["within"].toObject()["0.5"].toDouble(), 100.0);
        QCOMPARE(o["within"].toObject()["0.02"].toDouble(), 0.0);
        QVERIFY(o["within_by_fix"].toObject().contains("rtk_fixed") ||
                o["within_by_fix"].toObject().size() == 1);
    }
};

QTEST_GUILESS_MAIN(TstAccuracy)
#include "tst_accuracy.moc"
