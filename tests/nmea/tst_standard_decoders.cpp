// Standard sentence decoders across NMEA 2.x to 4.11: values, empty fields, malformed fields.
#include "core/sentence_builder.h"
#include "decode_helper.h"

#include <QJsonArray>
#include <QTest>
#include <cmath>

using gnss::test::decodeOne;

namespace {
bool near(const QJsonValue &v, double expected, double tol = 1e-9) {
    return v.isDouble() && std::abs(v.toDouble() - expected) < tol;
}
} // namespace

class TstStandardDecoders : public QObject {
    Q_OBJECT
private slots:
    void ggaDecodesEveryField() {
        const auto d =
                decodeOne("$GPGGA,092750.000,5321.6802,N,00630.3372,W,1,8,1.03,61.7,M,55.2,M,,*76");
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["time"].toString(), QString("09:27:50.000"));
        QVERIFY(near(d.data["lat"], 53 + 21.6802 / 60));
        QVERIFY(near(d.data["lon"], -(6 + 30.3372 / 60)));
        QCOMPARE(d.data["quality"].toInt(), 1);
        QCOMPARE(d.data["sats_used"].toInt(), 8);
        QVERIFY(near(d.data["hdop"], 1.03));
        QVERIFY(near(d.data["alt_msl"], 61.7));
        QVERIFY(near(d.data["geoid_sep"], 55.2));
        QVERIFY(d.data["dgps_age"].isNull());
        QVERIFY(d.data["dgps_station"].isNull());
    }

    void emptyNoFixSentencesDecodeToNulls_data() {
        QTest::addColumn<QString>("line");
        QTest::newRow("GGA") << "$GPGGA,000008.00,,,,,0,,,,,,,,,*6C";
        QTest::newRow("GLL") << "$GNGLL,,,,,000007.00,V,N*53";
        QTest::newRow("GNS") << "$GPGNS,080520.00,,,,,11,,,,,*40";
        QTest::newRow("GSA") << "$GPGSA,A,1,,,,,,,,,,,,,9.9,9.9,9.9*30";
        QTest::newRow("RMC") << "$GPRMC,142353.00,V,,,,,,,,,300518,,,N*70";
        QTest::newRow("RMC 4.10") << "$GNRMC,141821.00,V,,,,,,,,,300518,,,N,V*19";
        QTest::newRow("GSV empty") << "$GPGSV,1,1,00*79";
    }
    void emptyNoFixSentencesDecodeToNulls() {
        QFETCH(QString, line);
        const auto d = decodeOne(line);
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.checksum, QString("ok"));
        if (d.data.contains("lat")) QVERIFY(d.data["lat"].isNull());
    }

    void gsaCarriesSystemIdIn410() {
        const auto d = decodeOne("$GNGSA,A,3,68,69,70,77,78,79,81,87,88,,,,1.0,0.5,0.8,2*13",
                                 {.lenient = true});
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["system_id"].toInt(), 2);
        QCOMPARE(d.data["ids"].toArray().size(), 9);
        QCOMPARE(d.data["satellites"].toArray()[0].toObject()["system"].toString(),
                 QString("GLONASS"));
        QCOMPARE(d.data["satellites"].toArray()[0].toObject()["prn"].toInt(), 4);
        QVERIFY(near(d.data["pdop"], 1.0));
        QVERIFY(near(d.data["vdop"], 0.8));
    }

    void gsaWithoutSystemIdInfersFromIds() {
        const auto d = decodeOne(
                "$GPGSA,A,3,001,010,011,012,013,015,017,018,019,024,028,030,1.0,0.5,0.8*33");
        QVERIFY2(d.ok, qPrintable(d.error));
        QVERIFY(d.data["system_id"].isNull());
        QCOMPARE(d.data["ids"].toArray().size(), 12);
        QCOMPARE(d.data["ids"].toArray()[0].toInt(), 1);
        QVERIFY(near(d.data["hdop"], 0.5));
    }

    void gsvReadsThreeDigitIdsAndNegativeElevations() {
        const auto d = decodeOne(
                "$GPGSV,08,01,32,002,33,059,47,004,-2,000,48,005,34,099,49,009,06,017,40*69");
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["total"].toInt(), 8);
        QCOMPARE(d.data["index"].toInt(), 1);
        QCOMPARE(d.data["in_view"].toInt(), 32);
        QVERIFY(d.data["signal_id"].isNull());
        const auto sats = d.data["satellites"].toArray();
        QCOMPARE(sats.size(), 4);
        QCOMPARE(sats[1].toObject()["prn"].toInt(), 4);
        QCOMPARE(sats[1].toObject()["elevation"].toInt(), -2);
        QCOMPARE(sats[1].toObject()["azimuth"].toInt(), 0);
        QCOMPARE(sats[1].toObject()["snr"].toInt(), 48);
    }

    void gsvSignalIdAndMissingSnr() {
        const auto d =
                decodeOne("$GAGSV,3,1,09,01,09,130,40,03,09,317,37,05,00,271,,08,06,005,,7*77");
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["signal_id"].toInt(), 7);
        const auto sats = d.data["satellites"].toArray();
        QCOMPARE(sats.size(), 4);
        QCOMPARE(sats[0].toObject()["system"].toString(), QString("Galileo"));
        QVERIFY(sats[2].toObject()["snr"].isNull());
        const auto last = decodeOne("$GAGSV,3,3,09,31,58,143,,7*43");
        QVERIFY2(last.ok, qPrintable(last.error));
        QCOMPARE(last.data["satellites"].toArray().size(), 1);
    }

    // GSV satellites and GSA ids printed at the receivers' fixed widths are read at once
    // (core/fixed_digits.h); the same values printed otherwise are read field by field. Both must
    // give the same message, or the same refusal.
    void fixedWidthFieldsReadAsAnyOther_data() {
        QTest::addColumn<QString>("fixedWidth");
        QTest::addColumn<QString>("otherwise");
        QTest::newRow("GSV satellites")
                << "GPGSV,3,1,12,01,05,000,31,02,12,037,32,03,19,074,33,04,26,111,35"
                << "GPGSV,3,1,12,1,5,0,31,2,12,37,32,3,19,74,33,4,26,111,35";
        QTest::newRow("GSV with signal id")
                << "GLGSV,2,1,08,65,05,000,31,66,12,037,32,67,19,074,33,68,26,111,35,1"
                << "GLGSV,2,1,08,65,5,000,31,66,12,037,32,67,19,074,33,68,26,111,35,1";
        QTest::newRow("GSV last of three") << "GBGSV,3,3,10,09,61,296,42,10,68,333,43,1"
                                           << "GBGSV,3,3,10,9,61,296,42,10,68,333,43,1";
        QTest::newRow("GSV largest values") << "GPGSV,1,1,02,99,90,360,99,98,00,000,00"
                                            << "GPGSV,1,1,02,99,90,360,99,98,0,0,0";
        QTest::newRow("GSV elevation out of range") << "GPGSV,1,1,01,01,91,000,31"
                                                    << "GPGSV,1,1,01,1,91,000,31";
        QTest::newRow("GSV azimuth out of range") << "GPGSV,1,1,01,01,05,361,31"
                                                  << "GPGSV,1,1,01,1,05,361,31";
        QTest::newRow("GSA twelve ids")
                << "GNGSA,A,3,01,02,03,04,05,06,07,08,09,10,11,12,1.1,0.6,0.9,1"
                << "GNGSA,A,3,1,2,3,4,5,6,7,8,9,10,11,12,1.1,0.6,0.9,1";
        QTest::newRow("GSA ids then empty slots")
                << "GNGSA,A,3,65,66,67,68,69,70,,,,,,,1.1,0.6,0.9,2"
                << "GNGSA,A,3,65,66,67,68,69,70,,,,,,,1.1,0.6,0.9,2";
        QTest::newRow("GSA sixteen ids")
                << "GPGSA,A,3,01,02,03,04,05,06,07,08,09,10,11,12,13,14,15,16,1.1,0.6,0.9"
                << "GPGSA,A,3,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,1.1,0.6,0.9";
    }
    void fixedWidthFieldsReadAsAnyOther() {
        QFETCH(QString, fixedWidth);
        QFETCH(QString, otherwise);
        const auto a = decodeOne(gnss::buildSentence(fixedWidth.toStdString()).c_str());
        const auto b = decodeOne(gnss::buildSentence(otherwise.toStdString()).c_str());
        QCOMPARE(a.ok, b.ok);
        if (!a.ok) {
            QVERIFY(!a.error.isEmpty());
            QCOMPARE(a.error, b.error);
            return;
        }
        // "id" is the number as printed: the same number either way.
        QCOMPARE(a.data, b.data);
        QVERIFY(a.data.contains("satellites"));
        QVERIFY(!a.data["satellites"].toArray().isEmpty());
    }

    void gsv411SignalIdsForEveryConstellation_data() {
        QTest::addColumn<QString>("line");
        QTest::addColumn<QString>("system");
        QTest::addColumn<int>("signal");
        QTest::newRow("GPS L5") << gnss::buildSentence("GPGSV,1,1,01,05,40,083,46,8").c_str()
                                << "GPS" << 8;
        QTest::newRow("BeiDou B2a")
                << gnss::buildSentence("GBGSV,1,1,01,19,40,083,46,5").c_str() << "BeiDou" << 5;
        QTest::newRow("QZSS L1") << gnss::buildSentence("GQGSV,1,1,01,02,40,083,46,1").c_str()
                                 << "QZSS" << 1;
        QTest::newRow("NavIC") << gnss::buildSentence("GIGSV,1,1,01,03,40,083,46,1").c_str()
                               << "NavIC" << 1;
    }
    void gsv411SignalIdsForEveryConstellation() {
        QFETCH(QString, line);
        QFETCH(QString, system);
        QFETCH(int, signal);
        const auto d = decodeOne(line);
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["signal_id"].toInt(), signal);
        QCOMPARE(d.data["satellites"].toArray()[0].toObject()["system"].toString(), system);
    }

    void rmcDecodesDateModeAndNavStatus() {
        const auto d = decodeOne(
                "$GNRMC,153632.00,A,5550.602949,N,03732.239610,E,000.00000,000.0,310518,,,R,V*28");
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["status"].toString(), QString("A"));
        QCOMPARE(d.data["date"].toString(), QString("2018-05-31"));
        QCOMPARE(d.data["mode"].toString(), QString("R"));
        QCOMPARE(d.data["nav_status"].toString(), QString("V"));
        QVERIFY(near(d.data["sog_knots"], 0.0));
        QVERIFY(near(d.data["lat"], 55 + 50.602949 / 60));
        const auto west = decodeOne(
                gnss::buildSentence(
                        "GPRMC,123519,A,4807.038,N,01131.000,W,022.4,084.4,230394,003.1,W")
                        .c_str());
        QVERIFY2(west.ok, qPrintable(west.error));
        QVERIFY(near(west.data["mag_var"], -3.1));
        QCOMPARE(west.data["date"].toString(), QString("1994-03-23"));
    }

    void gnsModeOfAnyLength() {
        const auto two = decodeOne(
                "$GNGNS,153632.00,5550.602949,N,03732.239610,E,RR,15,0.7,00192.247,0014.4,,,V*24");
        QVERIFY2(two.ok, qPrintable(two.error));
        QCOMPARE(two.data["mode"].toString(), QString("RR"));
        QCOMPARE(two.data["sats_used"].toInt(), 15);
        QCOMPARE(two.data["nav_status"].toString(), QString("V"));
        const auto four = decodeOne("$GPGNS,080839.00,5550.611145,N,03732.253491,E,DNNN,10,0.8,"
                                    "00182.290,0014.4,001.0,0000,V*15");
        QVERIFY2(four.ok, qPrintable(four.error));
        QCOMPARE(four.data["mode"].toString(), QString("DNNN"));
        QVERIFY(near(four.data["dgps_age"], 1.0));
        QCOMPARE(four.data["dgps_station"].toInt(), 0);
    }

    void otherStandardSentences_data() {
        QTest::addColumn<QString>("line");
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("value");
        QTest::newRow("VTG") << gnss::buildSentence("GPVTG,224.5,T,,M,0.5,N,0.9,K,A").c_str()
                             << "cog_true" << 224.5;
        QTest::newRow("VTG 1.x") << gnss::buildSentence("GPVTG,054.7,034.4,005.5,010.2").c_str()
                                 << "sog_kmh" << 10.2;
        QTest::newRow("HDT") << gnss::buildSentence("GPHDT,274.07,T").c_str() << "heading"
                             << 274.07;
        QTest::newRow("DTM") << "$GPDTM,999,,0.002,S,0.005,E,005.8,W84*1A"
                             << "lat_offset_min" << -0.002;
        QTest::newRow("GST") << gnss::buildSentence(
                                        "GPGST,172814.0,0.006,0.023,0.020,273.6,0.023,0.020,0.031")
                                        .c_str()
                             << "sd_alt" << 0.031;
        QTest::newRow("ZDA") << "$GPZDA,072914.00,31,05,2018,+00,00*48"
                             << "tz_hours" << 0.0;
        QTest::newRow("TXT") << gnss::buildSentence("GPTXT,01,01,02,ANTSTATUS=OK").c_str() << "id"
                             << 2.0;
    }
    void otherStandardSentences() {
        QFETCH(QString, line);
        QFETCH(QString, key);
        QFETCH(double, value);
        const auto d = decodeOne(line);
        QVERIFY2(d.ok, qPrintable(d.error));
        QVERIFY2(near(d.data[key], value), qPrintable(key));
    }

    void zdaAndTxtKeepTheirText() {
        const auto z = decodeOne("$GNZDA,072836.00,31,05,2018,+00,00*57");
        QCOMPARE(z.data["date"].toString(), QString("2018-05-31"));
        const auto t =
                decodeOne(gnss::buildSentence("GPTXT,01,01,02,u-blox ag - www.u-blox.com").c_str());
        QCOMPARE(t.data["text"].toString(), QString("u-blox ag - www.u-blox.com"));
    }

    // The first and last years a ZDA may give (four digits, none before GPS).
    void zdaTakesTheYearsOfFourDigitsSinceGps_data() {
        QTest::addColumn<QString>("year");
        QTest::newRow("1980") << "1980";
        QTest::newRow("2026") << "2026";
        QTest::newRow("9999") << "9999";
    }
    void zdaTakesTheYearsOfFourDigitsSinceGps() {
        QFETCH(QString, year);
        const auto d = decodeOne(QString::fromStdString(
                gnss::buildSentence(("GPZDA,072836.00,06,01," + year + ",+00,00").toStdString())));
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["date"].toString(), year + "-01-06");
    }

    void queryNamesRequesterListenerAndAddress() {
        const auto d = decodeOne("$GPGPQ,PNVGTST*21");
        QVERIFY2(d.ok, qPrintable(d.error));
        QCOMPARE(d.data["requester"].toString(), QString("GP"));
        QCOMPARE(d.data["listener"].toString(), QString("GP"));
        QCOMPARE(d.data["address"].toString(), QString("PNVGTST"));
    }

    void malformedFieldsAreReportedNotThrown_data() {
        QTest::addColumn<QString>("body");
        QTest::addColumn<QString>("errorPart");
        QTest::newRow("GGA bad lat")
                << "GPGGA,120000,48x7.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"
                << "latitude";
        QTest::newRow("GGA bad hemisphere")
                << "GPGGA,120000,4807.038,Q,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"
                << "hemisphere";
        QTest::newRow("GGA bad quality")
                << "GPGGA,120000,4807.038,N,01131.000,E,x,08,0.9,545.4,M,46.9,M,,"
                << "quality";
        QTest::newRow("GGA short") << "GPGGA,120000,4807.038"
                                   << "expected at least";
        QTest::newRow("RMC bad date")
                << "GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,330394,,,"
                << "date";
        QTest::newRow("RMC bad time")
                << "GPRMC,2561xx,A,4807.038,N,01131.000,E,022.4,084.4,230394,,,"
                << "time";
        QTest::newRow("ZDA year of two digits") << "GPZDA,072836.00,31,05,18,+00,00"
                                                << "(year): out of range";
        QTest::newRow("ZDA year before GPS") << "GPZDA,072836.00,31,05,1979,+00,00"
                                             << "(year): out of range";
        QTest::newRow("ZDA year of nine digits") << "GPZDA,072836.00,31,05,200000000,+00,00"
                                                 << "(year): out of range";
        QTest::newRow("ZDA negative year") << "GPZDA,072836.00,31,05,-2018,+00,00"
                                           << "(year): out of range";
        QTest::newRow("GSV index beyond total") << "GPGSV,2,3,08,01,40,083,46"
                                                << "sentence number";
        QTest::newRow("GSV elevation") << "GPGSV,1,1,01,01,95,083,46"
                                       << "elevation";
        QTest::newRow("GSA bad id") << "GPGSA,A,3,0x,,,,,,,,,,,,1.0,0.5,0.8"
                                    << "satellite id";
    }
    void malformedFieldsAreReportedNotThrown() {
        QFETCH(QString, body);
        QFETCH(QString, errorPart);
        const auto d = decodeOne(QString::fromStdString(gnss::buildSentence(body.toStdString())));
        QVERIFY(!d.ok);
        QVERIFY2(d.error.contains(errorPart), qPrintable(d.error));
    }
};

QTEST_APPLESS_MAIN(TstStandardDecoders)
#include "tst_standard_decoders.moc"
