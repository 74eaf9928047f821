// GeoS-5 satellite numbering (sections 3.4-3.5, v2.x and v4.10) and GGA quality (table 2).
#include "core/sentence_builder.h"
#include "decode_helper.h"
#include "geostar/geostar_dialect.h"

#include <QJsonArray>
#include <QTest>

using namespace gnss;

Q_DECLARE_METATYPE(gnss::Constellation)
Q_DECLARE_METATYPE(gnss::FixType)

class TstGeostarNumbering : public QObject {
    Q_OBJECT
private slots:
    void satelliteIdsMapToSystemAndPrn_data();
    void satelliteIdsMapToSystemAndPrn();
    void threeDigitIdsInGsvAndGsa();
    void v410GsaSystemIdSelectsTheConstellation();
    void ggaQualityMeansWhatTable2Says_data();
    void ggaQualityMeansWhatTable2Says();
};

void TstGeostarNumbering::satelliteIdsMapToSystemAndPrn_data() {
    QTest::addColumn<Constellation>("context"); // from the talker or the GSA system id
    QTest::addColumn<int>("id");
    QTest::addColumn<Constellation>("system");
    QTest::addColumn<int>("prn");
    using C = Constellation;
    // v2.x, everything under GP.
    QTest::newRow("v2 GPS 1") << C::Gps << 1 << C::Gps << 1;
    QTest::newRow("v2 GPS 32") << C::Gps << 32 << C::Gps << 32;
    QTest::newRow("v2 SBAS 33 = PRN 120") << C::Gps << 33 << C::Sbas << 120;
    QTest::newRow("v2 SBAS 64") << C::Gps << 64 << C::Sbas << 151;
    QTest::newRow("v2 GLONASS 65 = slot 1") << C::Gps << 65 << C::Glonass << 1;
    QTest::newRow("v2 GLONASS 88 = slot 24") << C::Gps << 88 << C::Glonass << 24;
    QTest::newRow("v2 GLONASS 96") << C::Gps << 96 << C::Glonass << 32;
    QTest::newRow("v2 Galileo 101 = E01") << C::Gps << 101 << C::Galileo << 1;
    QTest::newRow("v2 Galileo 136 = E36") << C::Gps << 136 << C::Galileo << 36;
    QTest::newRow("v2 Galileo under GN") << C::Unknown << 119 << C::Galileo << 19;
    QTest::newRow("v2 Galileo under GA") << C::Galileo << 130 << C::Galileo << 30;
    QTest::newRow("v2 GLONASS under GL") << C::Glonass << 68 << C::Glonass << 4;
    QTest::newRow("v2 QZSS 193 = J01") << C::Gps << 193 << C::Qzss << 1;
    QTest::newRow("v2 QZSS 197 = J05") << C::Gps << 197 << C::Qzss << 5;
    // v4.10, per talker / system id.
    QTest::newRow("v4 GA 1") << C::Galileo << 1 << C::Galileo << 1;
    QTest::newRow("v4 GA 36") << C::Galileo << 36 << C::Galileo << 36;
    QTest::newRow("v4 QZSS 1 (system id 15)") << C::Qzss << 1 << C::Qzss << 1;
    QTest::newRow("v4 QZSS 5") << C::Qzss << 5 << C::Qzss << 5;
    QTest::newRow("v4 GP SBAS 36") << C::Gps << 36 << C::Sbas << 123;
    QTest::newRow("v4 GL 70") << C::Glonass << 70 << C::Glonass << 6;
}

void TstGeostarNumbering::satelliteIdsMapToSystemAndPrn() {
    QFETCH(Constellation, context);
    QFETCH(int, id);
    QFETCH(Constellation, system);
    QFETCH(int, prn);
    const SatelliteRef s = geostar::dialect().mapSatellite(context, id);
    QCOMPARE(toString(s.system), toString(system));
    QCOMPARE(s.prn, prn);
}

void TstGeostarNumbering::threeDigitIdsInGsvAndGsa() {
    DecoderOptions o;
    o.dialect = "geostar";
    const auto gsv = test::decodeOne(
            "$GPGSV,08,08,32,119,06,099,36,120,-2,000,28,124,42,191,45,125,55,274,44*6A", o);
    QVERIFY2(gsv.ok, qPrintable(gsv.error));
    const QJsonArray sats = gsv.data["satellites"].toArray();
    QCOMPARE(sats[0].toObject()["system"].toString(), QString("Galileo"));
    QCOMPARE(sats[0].toObject()["prn"].toInt(), 19);
    QCOMPARE(sats[1].toObject()["elevation"].toInt(), -2);
    const auto gsa = test::decodeOne(
            "$GPGSA,A,3,001,010,011,012,013,015,017,018,019,024,028,030,1.0,0.5,0.8*33", o);
    QVERIFY2(gsa.ok, qPrintable(gsa.error));
    QCOMPARE(gsa.data["ids"].toArray().size(), 12);
    QCOMPARE(gsa.data["ids"].toArray()[0].toInt(), 1);
    QCOMPARE(gsa.data["satellites"].toArray()[0].toObject()["system"].toString(), QString("GPS"));
}

void TstGeostarNumbering::v410GsaSystemIdSelectsTheConstellation() {
    DecoderOptions o;
    o.dialect = "geostar";
    // System id 15 = QZSS (GeoStar), ids 1-5.
    const auto qzss = test::decodeOne(
            gnss::buildSentence("GNGSA,A,3,01,02,,,,,,,,,,,1.0,0.5,0.8,15").c_str(), o);
    QVERIFY2(qzss.ok, qPrintable(qzss.error));
    QCOMPARE(qzss.data["system_id"].toInt(), 15);
    QCOMPARE(qzss.data["satellites"].toArray()[1].toObject()["system"].toString(), QString("QZSS"));
    QCOMPARE(qzss.data["satellites"].toArray()[1].toObject()["prn"].toInt(), 2);
    const auto gal = test::decodeOne("$GNGSA,A,3,04,19,30,,,,,,,,,,,,,1.0,0.5,0.8,3*30",
                                     DecoderOptions{.dialect = "geostar", .lenient = true});
    QVERIFY2(gal.ok, qPrintable(gal.error));
    QCOMPARE(gal.data["satellites"].toArray()[2].toObject()["system"].toString(),
             QString("Galileo"));
    QCOMPARE(gal.data["satellites"].toArray()[2].toObject()["prn"].toInt(), 30);
}

void TstGeostarNumbering::ggaQualityMeansWhatTable2Says_data() {
    QTest::addColumn<int>("quality");
    QTest::addColumn<FixType>("fix");
    QTest::newRow("0 none") << 0 << FixType::None;
    QTest::newRow("1 autonomous") << 1 << FixType::Fix3D;
    QTest::newRow("2 differential/SBAS") << 2 << FixType::Dgnss;
    QTest::newRow("4 fixed RTK") << 4 << FixType::RtkFixed;
    QTest::newRow("5 float RTK") << 5 << FixType::RtkFloat;
    QTest::newRow("6 extrapolated") << 6 << FixType::Estimated;
    QTest::newRow("7 fixed coordinates") << 7 << FixType::Manual;
    QTest::newRow("9 GeoPath") << 9 << FixType::Fix3D;
}

void TstGeostarNumbering::ggaQualityMeansWhatTable2Says() {
    QFETCH(int, quality);
    QFETCH(FixType, fix);
    QCOMPARE(toString(geostar::dialect().ggaQuality(quality)), toString(fix));
}

QTEST_APPLESS_MAIN(TstGeostarNumbering)
#include "tst_geostar_numbering.moc"
