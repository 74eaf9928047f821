// Every standard-sentence example printed in the specs (../shared/specs/examples.tsv): ok ones
// decode to the values printed in them, bad ones are flagged and decode only when lenient, typos
// decode in their corrected form. Values are cross-checked against the sentence's own text.
#include "decode_helper.h"
#include "examples_table.h"

#include <QJsonArray>
#include <QTest>
#include <cmath>

using gnss::test::decodeOne;

namespace {

QStringList fieldsOf(const QString &sentence) {
    QString body = sentence.mid(1);
    body = body.left(body.lastIndexOf('*'));
    QStringList f = body.split(',');
    for (auto &s : f) s = s.trimmed();
    f.removeFirst(); // address
    return f;
}

double dm(const QString &v, const QString &hemi) {
    const double raw = v.toDouble();
    const double deg = std::floor(raw / 100);
    const double d = deg + (raw - deg * 100) / 60;
    return (hemi == "S" || hemi == "W") ? -d : d;
}

void expectNumber(const QJsonObject &o, const char *key, const QString &text) {
    if (text.isEmpty()) {
        QVERIFY2(o[key].isNull(), key);
        return;
    }
    QVERIFY2(std::abs(o[key].toDouble() - text.toDouble()) < 1e-9, key);
}

void expectCoordinate(const QJsonObject &o, const char *key, const QString &v, const QString &h) {
    if (v.isEmpty()) {
        QVERIFY2(o[key].isNull(), key);
        return;
    }
    QVERIFY2(std::abs(o[key].toDouble() - dm(v, h)) < 1e-10, key);
}

// The decoded values must be the ones printed in the sentence.
void crossCheck(const QString &sentence, const QJsonObject &d) {
    const QStringList f = fieldsOf(sentence);
    const QString type = sentence.mid(3, 3);
    if (type == "GGA") {
        expectCoordinate(d, "lat", f[1], f[2]);
        expectCoordinate(d, "lon", f[3], f[4]);
        expectNumber(d, "quality", f[5]);
        expectNumber(d, "sats_used", f[6]);
        expectNumber(d, "hdop", f[7]);
        expectNumber(d, "alt_msl", f[8]);
        expectNumber(d, "geoid_sep", f[10]);
        expectNumber(d, "dgps_age", f.value(12));
    } else if (type == "RMC") {
        QCOMPARE(d["status"].toString(), f[1]);
        expectCoordinate(d, "lat", f[2], f[3]);
        expectCoordinate(d, "lon", f[4], f[5]);
        expectNumber(d, "sog_knots", f[6]);
        expectNumber(d, "cog", f[7]);
        int di = 8; // GeoS-5's no-fix RMC prints two extra empty fields before the date
        while (di < f.size() && f[di].size() != 6) ++di;
        QCOMPARE(d["date"].toString(),
                 QString("20%1-%2-%3").arg(f[di].mid(4, 2), f[di].mid(2, 2), f[di].left(2)));
        QCOMPARE(d["mode"].toString(), f[di + 3]);
    } else if (type == "GLL") {
        expectCoordinate(d, "lat", f[0], f[1]);
        expectCoordinate(d, "lon", f[2], f[3]);
        QCOMPARE(d["status"].toString(), f[5]);
        QCOMPARE(d["mode"].toString(), f[6]);
    } else if (type == "GSA") {
        int ids = 0;
        for (int i = 2; i < f.size() - 3; ++i)
            if (!f[i].isEmpty() && !f[i].contains('.') && i < 2 + 16) ++ids;
        QVERIFY(d["ids"].toArray().size() >= 1 || f[1] == "1");
        QCOMPARE(d["fix"].toInt(), f[1].toInt());
    } else if (type == "GSV") {
        QCOMPARE(d["total"].toInt(), f[0].toInt());
        QCOMPARE(d["index"].toInt(), f[1].toInt());
        QCOMPARE(d["in_view"].toInt(), f[2].toInt());
        const auto sats = d["satellites"].toArray();
        for (int i = 0; i < sats.size(); ++i) {
            const auto s = sats[i].toObject();
            QCOMPARE(s["id"].toInt(), f[3 + 4 * i].toInt());
            expectNumber(s, "elevation", f[4 + 4 * i]);
            expectNumber(s, "azimuth", f[5 + 4 * i]);
            expectNumber(s, "snr", f[6 + 4 * i]);
        }
    } else if (type == "GNS") {
        QCOMPARE(d["mode"].toString(), f[5]);
        expectCoordinate(d, "lat", f[1], f[2]);
    } else if (type == "ZDA") {
        QCOMPARE(d["date"].toString(), QString("%1-%2-%3").arg(f[3], f[2], f[1]));
    } else if (type == "VTG") {
        expectNumber(d, "cog_true", f[0]);
        expectNumber(d, "sog_knots", f.value(f.indexOf("N") - 1));
        QCOMPARE(d["mode"].toString(), f.last());
    }
}

bool isStandard(const std::string &s) {
    return s.rfind("$GPSGG", 0) != 0 && s.size() > 6 && s[1] != 'P';
}

} // namespace

class TstStandardExamples : public QObject {
    Q_OBJECT
private slots:
    void specExampleDecodes_data() {
        QTest::addColumn<QString>("sentence");
        QTest::addColumn<QString>("verdict");
        const auto examples = gnss::test::loadSpecExamples();
        if (examples.empty()) QSKIP("../shared/specs/examples.tsv not present");
        int n = 0;
        for (const auto &e : examples) {
            if (!isStandard(e.sentence())) continue;
            const QString s = QString::fromStdString(e.sentence());
            QTest::newRow(qPrintable(QString("%1 %2").arg(++n).arg(s.left(40))))
                    << s << QString::fromStdString(e.verdict);
        }
        QVERIFY(n >= 60);
    }
    void specExampleDecodes() {
        QFETCH(QString, sentence);
        QFETCH(QString, verdict);
        const auto strict = decodeOne(sentence);
        if (verdict == "bad") {
            QVERIFY(!strict.ok);
            QCOMPARE(strict.checksum, QString("bad"));
            QVERIFY2(strict.error.contains("checksum"), qPrintable(strict.error));
            const auto lenient = decodeOne(sentence, {.lenient = true});
            QVERIFY2(lenient.ok, qPrintable(lenient.error));
            QCOMPARE(lenient.checksum, QString("bad"));
            crossCheck(sentence, lenient.data);
        } else {
            QVERIFY2(strict.ok, qPrintable(strict.error));
            QCOMPARE(strict.checksum, QString("ok"));
            crossCheck(sentence, strict.data);
        }
    }

    void specValuesTypedFromTheSpec() {
        // GeoS-5 spec 3.1: RTK fixed example.
        auto d = decodeOne("$GPGGA,153556.00,5550.602948,N,03732.239612,E,4,15,0.7,00192.245,M,"
                           "0014.4,M,000.6,0100*46");
        QVERIFY(d.ok);
        QCOMPARE(d.data["quality"].toInt(), 4);
        QCOMPARE(d.data["sats_used"].toInt(), 15);
        QCOMPARE(d.data["alt_msl"].toDouble(), 192.245);
        QCOMPARE(d.data["dgps_station"].toInt(), 100);
        QCOMPARE(d.data["time"].toString(), QString("15:35:56.000"));
        // 3.1: GeoPath quality 9 with three-decimal geoid separation.
        d = decodeOne("$GPGGA,040717.00,5550.610226,N,03732.250730,E,9,18,0.6,00187.429,M,0014.442,"
                      "M,,*6A");
        QVERIFY(d.ok);
        QCOMPARE(d.data["quality"].toInt(), 9);
        QCOMPARE(d.data["geoid_sep"].toDouble(), 14.442);
        // 3.5: v2.x GSV with GLONASS 65-96 and Galileo 101-136 under the GP talker.
        d = decodeOne("$GPGSV,08,06,32,081,24,062,46,082,75,029,51,083,44,256,49,102,16,322,36*7D");
        QVERIFY(d.ok);
        const auto sats = d.data["satellites"].toArray();
        QCOMPARE(sats[0].toObject()["system"].toString(), QString("GLONASS"));
        QCOMPARE(sats[0].toObject()["prn"].toInt(), 17);
        QCOMPARE(sats[3].toObject()["id"].toInt(), 102);
    }
};

QTEST_APPLESS_MAIN(TstStandardExamples)
#include "tst_standard_examples.moc"
