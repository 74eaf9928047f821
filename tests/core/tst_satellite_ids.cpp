// Satellite numbering: (talker or system id, NMEA id) → (constellation, PRN or slot).
#include "core/satellite.h"

#include <QTest>

using gnss::Constellation;

Q_DECLARE_METATYPE(gnss::Constellation)

class TstSatelliteIds : public QObject {
    Q_OBJECT
private slots:
    void idsMapByTalkerAndRange_data() {
        QTest::addColumn<QString>("talker");
        QTest::addColumn<int>("id");
        QTest::addColumn<gnss::Constellation>("system");
        QTest::addColumn<int>("prn");
        QTest::newRow("GP GPS") << "GP" << 5 << Constellation::Gps << 5;
        QTest::newRow("GP three-digit GPS") << "GP" << 1 << Constellation::Gps << 1;
        QTest::newRow("GP SBAS 33-64") << "GP" << 36 << Constellation::Sbas << 123;
        QTest::newRow("GP SBAS PRN") << "GP" << 131 << Constellation::Sbas << 131;
        QTest::newRow("GP GLONASS 65-96") << "GP" << 68 << Constellation::Glonass << 4;
        QTest::newRow("GN GLONASS") << "GN" << 88 << Constellation::Glonass << 24;
        QTest::newRow("GL GLONASS 65-96") << "GL" << 70 << Constellation::Glonass << 6;
        QTest::newRow("GL GLONASS slot") << "GL" << 6 << Constellation::Glonass << 6;
        QTest::newRow("GA 4.10") << "GA" << 31 << Constellation::Galileo << 31;
        QTest::newRow("GA 2.x 101-136") << "GA" << 104 << Constellation::Galileo << 4;
        QTest::newRow("GA 301-336") << "GA" << 301 << Constellation::Galileo << 1;
        QTest::newRow("GB BeiDou") << "GB" << 12 << Constellation::BeiDou << 12;
        QTest::newRow("GB SiRF 201+") << "GB" << 201 << Constellation::BeiDou << 1;
        QTest::newRow("BD BeiDou") << "BD" << 30 << Constellation::BeiDou << 30;
        QTest::newRow("GQ QZSS") << "GQ" << 2 << Constellation::Qzss << 2;
        QTest::newRow("GQ QZSS 193+") << "GQ" << 194 << Constellation::Qzss << 2;
        QTest::newRow("GP QZSS 193+") << "GP" << 193 << Constellation::Qzss << 1;
        QTest::newRow("GI NavIC") << "GI" << 3 << Constellation::NavIC << 3;
        QTest::newRow("GN BeiDou 401+") << "GN" << 401 << Constellation::BeiDou << 1;
        QTest::newRow("GN Galileo 301+") << "GN" << 336 << Constellation::Galileo << 36;
        QTest::newRow("GN unknown range") << "GN" << 99 << Constellation::Unknown << 99;
    }
    void idsMapByTalkerAndRange() {
        QFETCH(QString, talker);
        QFETCH(int, id);
        QFETCH(gnss::Constellation, system);
        QFETCH(int, prn);
        const std::string t = talker.toStdString();
        const auto ref = gnss::mapSatelliteId(gnss::constellationOfTalker(t), id);
        QCOMPARE(int(ref.system), int(system));
        QCOMPARE(ref.prn, prn);
    }

    // The inline table answers as mapSatelliteId does, for every system and any id.
    void theInlineMappingIsMapSatelliteId() {
        for (int c = 0; c <= int(gnss::Constellation::NavIC); ++c)
            for (int id = -300; id <= 1000; ++id) {
                const auto system = static_cast<gnss::Constellation>(c);
                const auto inlined = gnss::mapSatelliteIdInline(system, id);
                const auto called = gnss::mapSatelliteId(system, id);
                if (!(inlined == called))
                    QFAIL(qPrintable(QString("system %1, id %2").arg(c).arg(id)));
            }
    }

    void systemIdsName41xConstellations() {
        QCOMPARE(int(gnss::constellationOfSystemId(1)), int(Constellation::Gps));
        QCOMPARE(int(gnss::constellationOfSystemId(2)), int(Constellation::Glonass));
        QCOMPARE(int(gnss::constellationOfSystemId(3)), int(Constellation::Galileo));
        QCOMPARE(int(gnss::constellationOfSystemId(4)), int(Constellation::BeiDou));
        QCOMPARE(int(gnss::constellationOfSystemId(5)), int(Constellation::Qzss));
        QCOMPARE(int(gnss::constellationOfSystemId(6)), int(Constellation::NavIC));
        QCOMPARE(int(gnss::constellationOfSystemId(15)), int(Constellation::Qzss)); // GeoStar
        QCOMPARE(int(gnss::constellationOfSystemId(9)), int(Constellation::Unknown));
        // With a system id, Galileo 1-36 is Galileo, not GPS.
        QCOMPARE(int(gnss::mapSatelliteId(Constellation::Galileo, 4).system),
                 int(Constellation::Galileo));
    }

    void labelsAndSignalsFollowTheConventions() {
        QCOMPARE(QString::fromStdString(gnss::satelliteLabel({Constellation::Gps, 5})),
                 QString("G05"));
        QCOMPARE(QString::fromStdString(gnss::satelliteLabel({Constellation::Glonass, 12})),
                 QString("R12"));
        QCOMPARE(QString::fromStdString(gnss::satelliteLabel({Constellation::Galileo, 31})),
                 QString("E31"));
        QCOMPARE(gnss::signalName(Constellation::Gps, 7), std::string_view("L5-I"));
        QCOMPARE(gnss::signalName(Constellation::Galileo, 7), std::string_view("E1-BC"));
        QCOMPARE(gnss::signalName(Constellation::Gps, 0), std::string_view(""));
        QCOMPARE(gnss::toString(Constellation::NavIC), std::string_view("NavIC"));
    }
};

QTEST_APPLESS_MAIN(TstSatelliteIds)
#include "tst_satellite_ids.moc"
