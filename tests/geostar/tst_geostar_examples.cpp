// Every GeoStar example of ../shared/specs/examples.tsv, decoded through the real StreamDecoder
// with the geostar dialect: ok ones decode to the values printed in the spec, the 24 with wrong
// printed checksums are flagged as bad and decode only when lenient, typos (the misprinted
// $GPGSGG/$GPGSSG/$GPGG addresses, blanks after commas) decode in their corrected form.
#include "decode_helper.h"
#include "examples_table.h"

#include <QJsonArray>
#include <QTest>

using gnss::DecoderOptions;
using gnss::test::decodeOne;

namespace {

DecoderOptions geostar(bool lenient) {
    DecoderOptions o;
    o.dialect = "geostar";
    o.lenient = lenient;
    return o;
}

QStringList fieldsOf(const QString &sentence) {
    QString body = sentence.mid(1, sentence.lastIndexOf('*') - 1);
    QStringList f = body.split(',');
    for (auto &s : f) s = s.trimmed();
    f.removeFirst();
    return f;
}

// The spec's values for the rows whose meaning the spec spells out (section 3 prose).
void checkSpecValues(const QString &s, const QJsonObject &d) {
    const QStringList f = fieldsOf(s);
    const QString type = s.mid(3, 3);
    if (type == "GGA") {
        QCOMPARE(d["quality"].toInt(), f[5].toInt());
        QCOMPARE(d["time"].toString().left(8),
                 f[0].left(2) + ":" + f[0].mid(2, 2) + ":" + f[0].mid(4, 2));
    } else if (type == "GSV") {
        // Every satellite printed is decoded with its (possibly three-digit) id and its
        // elevation, negative ones included.
        const QJsonArray sats = d["satellites"].toArray();
        const bool v4 = (f.size() - 3) % 4 == 1;
        const int n = (f.size() - 3 - (v4 ? 1 : 0)) / 4;
        QCOMPARE(sats.size(), n);
        for (int i = 0; i < n; ++i) {
            QCOMPARE(sats[i].toObject()["id"].toInt(), f[3 + 4 * i].toInt());
            QCOMPARE(sats[i].toObject()["elevation"].toInt(), f[4 + 4 * i].toInt());
            QVERIFY(sats[i].toObject()["system"].toString() != "unknown");
        }
        if (v4) QCOMPARE(d["signal_id"].toInt(), f.last().toInt());
    } else if (type == "GSA") {
        QCOMPARE(d["fix"].toInt(), f[1].toInt());
        QCOMPARE(d["hdop"].toDouble(), 0.5 + (f[1] == "1" ? 9.4 : 0.0));
        for (const auto &sat : d["satellites"].toArray())
            QVERIFY(sat.toObject()["system"].toString() != "unknown");
    } else if (type == "GNS") {
        if (s.contains(",,,,,") && !s.contains("NNNN")) {
            // Subsidiary per-system sentence: the count printed in the mode position.
            QCOMPARE(d["sats_used"].toInt(), f[5].toInt());
            QCOMPARE(d["mode"].toString(), QString());
        } else {
            QCOMPARE(d["mode"].toString(), f[5]);
            QCOMPARE(d["nav_status"].toString(), QString("V"));
        }
    } else if (type == "RMC") {
        QCOMPARE(d["status"].toString(), f[1]);
        QVERIFY(d["date"].toString().startsWith("2018-05-3"));
        QVERIFY(!d["mode"].isNull());
    } else if (type == "GLL") {
        QCOMPARE(d["mode"].toString(), f[6]);
    } else if (type == "VTG") {
        QCOMPARE(d["cog_true"].toDouble(), 224.5);
        QCOMPARE(d["sog_knots"].toDouble(), 0.0);
        QCOMPARE(d["mode"].toString(), f.last());
    } else if (type == "ZDA") {
        QCOMPARE(d["date"].toString(), QString("2018-05-31"));
    } else if (type == "DTM") {
        QCOMPARE(d["datum"].toString(), QString("999"));
        QCOMPARE(d["reference_datum"].toString(), QString("W84"));
    } else if (type == "RLM") {
        QCOMPARE(d["beacon_id"].toString(), QString("123456789ABCD12"));
        QCOMPARE(d["message_code"].toInt(), 3);
        QCOMPARE(d["service"].toString(), QString("message"));
        QCOMPARE(d["length"].toString(), QString("long"));
    } else if (type == "SGG") {
        if (f[0] == "JAMDET") {
            QCOMPARE(d["jamming_detected"].toBool(), true);
        } else if (f.size() == 1) {
            QCOMPARE(d["command"].toString(), f[0]); // every input command decodes too
        } else if (f[0] == "RQUERY") {
            QCOMPARE(d["config2"].toObject()["receiver_type"].toString(), QString("GeoS-5M"));
        } else if (f[0] == "NQUERY") {
            QCOMPARE(d["rate_hz"].toInt(), 1);
        }
    }
}

} // namespace

class TstGeostarExamples : public QObject {
    Q_OBJECT
private slots:
    void everySpecExampleDecodes_data();
    void everySpecExampleDecodes();
    void rqueryExampleKeepsNameFirmwareAndDate();
    void nqueryExampleShowsTheUnknownPositionAsSuch();
    void subsidiaryGnsCarriesPerSystemCountAgeAndStation();
    void unknownGpsggCommandIsAnErrorNotACrash();
};

void TstGeostarExamples::everySpecExampleDecodes_data() {
    QTest::addColumn<QString>("sentence");
    QTest::addColumn<QString>("verdict");
    const auto examples = gnss::test::loadSpecExamples();
    if (examples.empty()) QSKIP("../shared/specs/examples.tsv not available");
    int n = 0, bad = 0;
    for (const auto &e : examples) {
        if (e.vendor != "geostar") continue;
        ++n;
        bad += e.verdict == "bad";
        const QString s = QString::fromStdString(e.sentence());
        QTest::addRow("%d %s", n, qPrintable(s)) << s << QString::fromStdString(e.verdict);
    }
    QVERIFY(n >= 130);
    QCOMPARE(bad, 24);
}

void TstGeostarExamples::everySpecExampleDecodes() {
    QFETCH(QString, sentence);
    QFETCH(QString, verdict);
    const auto strict = decodeOne(sentence, geostar(false));
    if (verdict == "bad") {
        QVERIFY2(!strict.ok, "a wrong printed checksum must not decode by default");
        QCOMPARE(strict.checksum, QString("bad"));
        QVERIFY2(strict.error.contains("checksum"), qPrintable(strict.error));
        const auto lenient = decodeOne(sentence, geostar(true));
        QVERIFY2(lenient.ok, qPrintable(lenient.error));
        QCOMPARE(lenient.checksum, QString("bad"));
        checkSpecValues(sentence, lenient.data);
        return;
    }
    QVERIFY2(strict.ok, qPrintable(strict.error));
    QCOMPARE(strict.checksum, QString("ok"));
    checkSpecValues(sentence, strict.data);
}

void TstGeostarExamples::rqueryExampleKeepsNameFirmwareAndDate() {
    const auto d = decodeOne("$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C",
                             geostar(false));
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["receiver_name"].toString(), QString("GEOS-5"));
    QCOMPARE(d.data["firmware"].toString(), QString("V.5.102"));
    QCOMPARE(d.data["firmware_version"].toString(), QString("5.102"));
    QCOMPARE(d.data["firmware_date"].toString(), QString("2018-05-10"));
    QCOMPARE(d.data["status"].toObject()["raw"].toString(), QString("00083037"));
    QCOMPARE(d.data["config1"].toObject()["raw"].toString(), QString("802DC097"));
    QCOMPARE(d.data["config2"].toObject()["raw"].toString(), QString("F7FF8064"));
}

void TstGeostarExamples::nqueryExampleShowsTheUnknownPositionAsSuch() {
    // "Port 1, 1 Hz, NMEA v2.x, outputs GGA, GSA, GSV, ZDA, DTM" (3.12, order from
    // docs/spec-notes.md).
    const auto d = decodeOne("$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71", geostar(false));
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["port"].toInt(), 1);
    QCOMPARE(d.data["rate_code"].toInt(), 3);
    QCOMPARE(d.data["rate_hz"].toInt(), 1);
    QCOMPARE(d.data["nmea_version"].toInt(), 2);
    const QJsonArray m = d.data["messages"].toArray();
    QCOMPARE(m.size(), 10);
    QStringList on;
    for (const auto &v : m)
        if (v.toObject()["code"].toString() != "0") on << v.toObject()["name"].toString();
    QCOMPARE(on, QStringList({"GGA", "GSA", "GSV", "ZDA", "DTM"}));
    QVERIFY(m[6].toObject()["name"].isNull());
    QVERIFY(m[6].toObject()["note"].toString().contains("unknown"));
    QCOMPARE(m[0].toObject()["output"].toString(), QString("at the output rate"));
}

void TstGeostarExamples::subsidiaryGnsCarriesPerSystemCountAgeAndStation() {
    const auto d = decodeOne("$GLGNS,080606.00,,,,,09,,,,,001.0,0000,*7D", geostar(false));
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["sats_used"].toInt(), 9);
    QCOMPARE(d.data["dgps_age"].toDouble(), 1.0);
    QCOMPARE(d.data["dgps_station"].toInt(), 0);
    // RTK subsidiary as printed (one comma short): age 0.8 s, base station 100.
    const auto rtk = decodeOne("$GPGNS,153632.00,,,,,09,,,,000.8,0100*4D", geostar(true));
    QVERIFY2(rtk.ok, qPrintable(rtk.error));
    QCOMPARE(rtk.data["dgps_age"].toDouble(), 0.8);
    QCOMPARE(rtk.data["dgps_station"].toInt(), 100);
    QVERIFY(rtk.data["geoid_sep"].isNull());
}

void TstGeostarExamples::unknownGpsggCommandIsAnErrorNotACrash() {
    for (const char *line :
         {"$GPSGG,FOOBAR*00", "$GPSGG*00", "$GPSGG,RQUERY,GEOS-5*00",
          "$GPSGG,RQUERY,GEOS-5,V.5.102,100518,XYZ,802DC097,F7FF8064*00", "$GPSGG,NQUERY,1,9,2*00",
          "$GPSGG,CSTART,1*00", "$GPRLM,12,3,4,5*00", "$GPSGG,JAMDET,1*00"}) {
        const auto d = decodeOne(line, geostar(true));
        QVERIFY2(!d.ok, line);
        QVERIFY2(!d.error.isEmpty(), line);
    }
}

QTEST_APPLESS_MAIN(TstGeostarExamples)
#include "tst_geostar_examples.moc"
