// Every Nemerix example of examples.tsv decodes under the nemerix dialect to what the spec says
// it means. Placeholders ("*xx") read as "no checksum", which the dialect accepts; the "*00"
// examples (PNMRX106, 600, 601, 603) carry a wrong checksum: flagged bad and not decoded unless
// lenient. Also the input tolerance the dialect needs: no checksum, blanks after commas,
// lower-case checksum hex, renamed prefix, and the standard sentences as a VT002 sends them.
#include "decode_helper.h"
#include "examples_table.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

#include <map>

using gnss::test::decodeOne;

namespace {

gnss::DecoderOptions nemerix(bool lenient = false) {
    gnss::DecoderOptions o;
    o.dialect = "nemerix";
    o.lenient = lenient;
    return o;
}

// The spec's meaning of each example, as a subset of the decoded JSON.
const std::map<std::string, const char *> &expectedValues() {
    static const std::map<std::string, const char *> m = {
            {"$PNMRX100,0,4800,0*XX", R"({"protocol":0,"baud":4800,"parity":0})"},
            {"$PNMRX101,,,,,,,,,8,*XX",
             R"({"ecef_x":null,"fix_procedure":8,"fix_procedure_name":"factory reset"})"},
            {"$PNMRX101,-742507,-5462738, 3196706,*XX",
             R"({"ecef_x":-742507,"ecef_y":-5462738,"ecef_z":3196706,"resets_receiver":true})"},
            {"$PNMRX101, 4,*XX", R"({"fix_procedure":4,"fix_procedure_name":"cold start"})"},
            {"$PNMRX103, GSV, 2,GGA, 1,ZDA, 0*XX",
             R"({"entries":[{"id":"GSV","rate_s":2},{"id":"GGA","rate_s":1},
                            {"id":"ZDA","rate_s":0,"enabled":false}]})"},
            {"$PNMRX103, GSV, 2, GGA, 1, ZDA, 0,*XX",
             R"({"entries":[{"id":"GSV","rate_s":2},{"id":"GGA","rate_s":1},
                            {"id":"ZDA","rate_s":0,"enabled":false}]})"},
            {"$PNMRX103, ALL, 2*XX", R"({"entries":[{"id":"ALL","rate_s":2}]})"},
            {"$PNMRX103, ALL, 0*XX", R"({"entries":[{"id":"ALL","rate_s":0,"enabled":false}]})"},
            {"$PNMRX106, 0,500, -2000,-2000,-2000, 8257224, 8137000*00",
             R"({"correction":0,"datum":500,"user_defined":true,"dx":-2000,"dy":-2000,"dz":-2000,
                 "iflat_raw":8257224,"inverse_flattening":298.257224,"major_axis_raw":8137000,
                 "semi_major_axis_m":6378137})"},
            {"$PNMRX106, 1, 216,*XX", R"({"correction":1,"datum":216,"user_defined":false})"},
            {"$PNMRX107, 300, 1*XX", R"({"entries":[{"message":"300","mode":1}]})"},
            {"$PNMRX107, 301, 2*XX",
             R"({"entries":[{"message":"301","mode":2,"mode_name":"send on change"}]})"},
            {"$PNMRX107, ALL, 2*XX", R"({"entries":[{"message":"ALL","mode":2}]})"},
            {"$PNMRX110, 0,-2:0*XX",
             R"({"masks":[{"id":0,"name":"local_time_zone","text":"-2:0","tz_minutes":-120}]})"},
            {"$PNMRX110, 4, 35*XX", R"({"masks":[{"id":4,"name":"min_snr","value":35}]})"},
            {"$PNMRX111*XX", R"({"bits":null,"named":null,"actions":[]})"},
            {"$PNMRX112, 1, 5*XX", R"({"mode":1,"mode_name":"LDCM1","off_period_s":5})"},
            {"$PNMRX113*XX", R"({"command":"PNMRX113"})"},
            {"$PNMRX600*00", R"({"command":"PNMRX600 request"})"},
            {"$PNMRX601*00", R"({"command":"PNMRX601"})"},
            {"$PNMRX603*00", R"({"command":"PNMRX603 request"})"},
            {"$PNMRX603*XX", R"({"command":"PNMRX603 request"})"},
    };
    return m;
}

bool subset(const QJsonValue &expected, const QJsonValue &actual, QString &where) {
    if (expected.isObject()) {
        const auto e = expected.toObject();
        const auto a = actual.toObject();
        for (auto it = e.begin(); it != e.end(); ++it) {
            if (!a.contains(it.key())) {
                where = "missing key " + it.key();
                return false;
            }
            if (!subset(it.value(), a.value(it.key()), where)) {
                where = it.key() + "." + where;
                return false;
            }
        }
        return true;
    }
    if (expected.isArray()) {
        const auto e = expected.toArray();
        const auto a = actual.toArray();
        if (e.size() != a.size()) {
            where = "array size";
            return false;
        }
        for (qsizetype i = 0; i < e.size(); ++i)
            if (!subset(e[i], a[i], where)) return false;
        return true;
    }
    if (expected.isDouble() && actual.isDouble()) {
        if (qAbs(expected.toDouble() - actual.toDouble()) <=
            1e-9 * qMax(1.0, qAbs(expected.toDouble())))
            return true;
    } else if (expected == actual) {
        return true;
    }
    where = "value " +
            QString::fromUtf8(QJsonDocument(QJsonArray{actual}).toJson(QJsonDocument::Compact));
    return false;
}

} // namespace

class TstNemerixExamples : public QObject {
    Q_OBJECT
private slots:
    void everySpecExampleDecodes_data();
    void everySpecExampleDecodes();
    void everyExampleHasExpectedValues();
    void sentenceWithoutChecksumIsAccepted();
    void blanksAfterCommasAreTrimmed();
    void lowerCaseChecksumHexIsAccepted();
    void renamedPrefixDecodesThroughAlias();
    void standardSentencesAsTheVt002SendsThem();
    void garbageNeverCrashes();
    void randomFieldsNeverCrash();
};

void TstNemerixExamples::everySpecExampleDecodes_data() {
    QTest::addColumn<QString>("sentence");
    QTest::addColumn<QString>("verdict");
    QTest::addColumn<QString>("computed");
    const auto examples = gnss::test::loadSpecExamples();
    int n = 0;
    for (const auto &e : examples) {
        if (e.vendor != "nemerix") continue;
        QTest::newRow(e.printed.c_str())
                << QString::fromStdString(e.sentence()) << QString::fromStdString(e.verdict)
                << QString::fromStdString(e.computedChecksum);
        ++n;
    }
    if (n == 0) QSKIP("examples.tsv not found (shared folder absent)");
}

void TstNemerixExamples::everySpecExampleDecodes() {
    QFETCH(QString, sentence);
    QFETCH(QString, verdict);
    QFETCH(QString, computed);

    // The checksum examples.tsv computed is the one our sentence code computes.
    gnss::Sentence s;
    const std::string line = sentence.toStdString();
    QVERIFY(s.parse(line));
    QCOMPARE(QString::asprintf("%02X", s.computedChecksum()), computed);

    const auto strict = decodeOne(sentence, nemerix());
    const auto lenient = decodeOne(sentence, nemerix(true));
    if (verdict == "placeholder") {
        // "*xx" is no checksum at all, which Nemerix allows.
        QCOMPARE(strict.checksum, QString("missing"));
        QVERIFY2(strict.ok, qPrintable(strict.error));
    } else if (verdict == "bad") {
        // "*00" is a real (wrong) checksum: flagged, not decoded unless lenient.
        QCOMPARE(strict.checksum, QString("bad"));
        QVERIFY(!strict.ok);
        QVERIFY2(strict.error.contains("checksum mismatch"), qPrintable(strict.error));
        QVERIFY2(lenient.ok, qPrintable(lenient.error));
    } else {
        QVERIFY2(strict.ok, qPrintable(strict.error));
    }
    const auto it = expectedValues().find(line);
    QVERIFY2(it != expectedValues().end(), "example without expected values in this test");
    const auto expected = QJsonDocument::fromJson(it->second).object();
    QVERIFY2(!expected.isEmpty(), "expected JSON does not parse");
    QString where;
    QVERIFY2(subset(expected, lenient.data, where), qPrintable(where));
}

void TstNemerixExamples::everyExampleHasExpectedValues() {
    const auto examples = gnss::test::loadSpecExamples();
    if (examples.empty()) QSKIP("examples.tsv not found (shared folder absent)");
    int n = 0;
    for (const auto &e : examples)
        if (e.vendor == "nemerix") {
            ++n;
            QVERIFY2(expectedValues().count(e.sentence()), e.sentence().c_str());
        }
    QCOMPARE(n, static_cast<int>(expectedValues().size()));
}

void TstNemerixExamples::sentenceWithoutChecksumIsAccepted() {
    for (const char *line : {"$PNMRX110,4,35", "$PNMRX110,4,35*", "$PNMRX110,4,35*xx"}) {
        const auto d = decodeOne(line, nemerix());
        QVERIFY2(d.ok, line);
        QCOMPARE(d.checksum, QString("missing"));
    }
    // Without the dialect chosen, auto detection still finds the rule's dialect optional.
    const auto autoDetect = decodeOne("$PNMRX112,0");
    QVERIFY2(autoDetect.ok, qPrintable(autoDetect.error));
    // A standard sentence without checksum is accepted once the dialect is Nemerix.
    const auto gga = decodeOne("$GPGGA,123519.000,4807.0380,N,01131.0000,E,1,08,0.9,545.4,M,"
                               "46.9,M,,0000",
                               nemerix());
    QVERIFY2(gga.ok, qPrintable(gga.error));
}

void TstNemerixExamples::blanksAfterCommasAreTrimmed() {
    const auto d =
            decodeOne("$PNMRX106, 0, 500, -2000, -2000, -2000, 8257224, 8137000 ", nemerix());
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["dz"].toInt(), -2000);
    QCOMPARE(d.data["major_axis_raw"].toInt(), 8137000);
}

void TstNemerixExamples::lowerCaseChecksumHexIsAccepted() {
    // $PNMRX300 upload-style sentence with lower-case hex fields and checksum.
    const std::string body = "PNMRX302,5,0c,ff,fe,01,7f,80,ff,00";
    char cs[3];
    std::snprintf(cs, sizeof cs, "%02x", gnss::nmeaChecksum(body));
    const auto d = decodeOne(QString::fromStdString("$" + body + "*" + cs), nemerix());
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.checksum, QString("ok"));
    QCOMPARE(d.data["alpha1_raw"].toString(), QString("FF"));
    QCOMPARE(d.data["alpha1"].toDouble(), -1.0 / (1 << 27));
}

void TstNemerixExamples::renamedPrefixDecodesThroughAlias() {
    auto o = nemerix();
    o.addressAliases = {{"PXYZW", "PNMRX"}};
    const auto d = decodeOne("$PXYZW110,4,35", o);
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["masks"].toArray()[0].toObject()["value"].toDouble(), 35.0);
    const auto noAlias = decodeOne("$PXYZW110,4,35", nemerix());
    QVERIFY(!noAlias.ok);
}

void TstNemerixExamples::standardSentencesAsTheVt002SendsThem() {
    // NMEA 3.0, GPS only, millisecond time, GSV with up to 12 satellites in three sentences.
    const char *lines[] = {
            "$GPGGA,092204.999,4250.5589,S,14718.5084,E,1,04,24.4,19.7,M,,,,0000*1F",
            "$GPGSA,A,3,01,20,19,13,,,,,,,,,40.4,24.4,32.2*0A",
            "$GPGSV,3,1,12,20,00,000,,10,00,000,,31,00,000,,27,00,000,*7C",
            "$GPGSV,3,3,12,30,00,000,,28,00,000,,26,00,000,,29,00,000,*78",
            "$GPRMC,092204.999,A,4250.5589,S,14718.5084,E,0.00,89.68,211200,,,A*74",
            "$GPVTG,89.68,T,,M,0.00,N,0.0,K,A*5F",
            "$GPZDA,092204.99,21,12,2000,-2,00*5B",
            "$GPGLL,4250.5589,S,14718.5084,E,092204.999,A,A*5B",
    };
    for (const char *l : lines) {
        const auto lenient = decodeOne(l, nemerix(true));
        QVERIFY2(lenient.ok, qPrintable(QString(l) + ": " + lenient.error));
    }
    const auto gsv = decodeOne(lines[2], nemerix(true));
    QCOMPARE(gsv.data["in_view"].toInt(), 12);
    QCOMPARE(gsv.data["satellites"].toArray().size(), 4);
}

void TstNemerixExamples::garbageNeverCrashes() {
    const char *lines[] = {
            "$PNMRX301",
            "$PNMRX301,5",
            "$PNMRX301,5,4,1,2",
            "$PNMRX301,5,1,,,,,,,,,",
            "$PNMRX300,,,,,,,,,,,,,",
            "$PNMRX300,40,1",
            "$PNMRX603,9",
            "$PNMRX603,0,1",
            "$PNMRX110,0,xx",
            "$PNMRX110,99,1",
            "$PNMRX110,4",
            "$PNMRX103,GGA",
            "$PNMRX103,FOO,1",
            "$PNMRX111,NOW",
            "$PNMRX111,300",
            "$PNMRX302,1,2",
            "$PNMRX303,1,ZZ",
            "$PNMRX106,0,300",
            "$PNMRX100,0,1234,0",
            "$PNMRX301,1,2,FF,FFFFFFFFFFFFFFFFF,0,0,0,0,0,0,0",
            "$PNMRX104,4807.038,N",
            "$PNMRX101,1,2",
    };
    for (const char *l : lines) {
        const auto d = decodeOne(l, nemerix(true));
        QVERIFY2(!d.ok, l);
        QVERIFY2(!d.error.isEmpty(), l);
    }
}

void TstNemerixExamples::randomFieldsNeverCrash() {
    // Every PNMRX address with random field counts and tokens: decoded or refused, never a crash.
    const char *numbers[] = {"100", "101", "103", "104", "106", "107", "108", "110", "111", "112",
                             "113", "300", "301", "302", "303", "304", "600", "601", "602", "603"};
    const char *tokens[] = {"",         " ",
                            "0",        "1",
                            "3",        "-1",
                            "FFFFFFFF", "ffffffffffffffffff",
                            "-",        ":",
                            "1:",       "-2:0",
                            "GGA",      "ALL",
                            "300",      "1.5",
                            "x",        "99999999999999999999",
                            "4",        "500",
                            "COLD",     "7FFFFF"};
    quint32 seed = 12345;
    auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
    int decoded = 0;
    for (int i = 0; i < 20000; ++i) {
        QString line = QString("$PNMRX") + numbers[next() % std::size(numbers)];
        const int n = static_cast<int>(next() % 20);
        for (int f = 0; f < n; ++f)
            line += QString(",") + tokens[(next() >> 8) % std::size(tokens)];
        const auto d = decodeOne(line, nemerix(true));
        QVERIFY(d.ok || !d.error.isEmpty());
        decoded += d.ok;
    }
    QVERIFY(decoded > 0);
}

QTEST_APPLESS_MAIN(TstNemerixExamples)
#include "tst_nemerix_examples.moc"
