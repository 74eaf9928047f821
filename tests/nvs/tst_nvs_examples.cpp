// Every NVS example of examples.tsv decodes, under the nvs dialect, to the values the spec
// prints; the pre-1.5 forms of PNVGBLS and PNVGIMU (no time tag) decode too.
#include "core/sentence_builder.h"
#include "decode_helper.h"
#include "examples_table.h"
#include "nvs/nvs_dialect.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <QTest>

#include <map>
#include <random>

using gnss::test::decodeOne;

namespace {

// The spec's values for each example (a subset of the decoded JSON, keys as gnss-cli prints).
const std::map<std::string, const char *> &expectedValues() {
    static const std::map<std::string, const char *> m = {
            {"$PNVGVER*4E", R"({"manufacturer":null,"device":null,"rtk_fw":null})"},
            {"$PNVGRZA,1,115200,1*6D", R"({"port":1,"baud":115200,"protocol":1})"},
            {"$PNVGRZB*45", R"({"port":null,"clear":true,"messages":[]})"},
            {"$PNVGRZB,PORT,2*6E", R"({"port":2,"clear":true,"messages":[]})"},
            {"$GPGPQ,PNVGTST*21", R"({"requester":"GP","listener":"GP","address":"PNVGTST"})"},
            {"$PNVGRZB,PNVGTST,10*18",
             R"({"port":null,"clear":false,"messages":[{"address":"PNVGTST","rate":10}]})"},
            {"$PNVGPPS,P,S,U,1,1000,D,0*62",
             R"({"type":"P","mode":"S","reference":"U","adjust":1,"duration":1000,
                 "validity":"D","cable_delay":0})"},
            {"$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7C",
             R"({"time":"14:55:05.200","roll":0.42,"pitch":0.37,"yaw":21.84,"acc_north":0.065,
                 "acc_east":0.064,"acc_down":-0.201})"},
            {"$PNVGBRS,091244.60,4604.566,-1242.064,-27.096,4769.223,344.90,-0.33,R*1A",
             R"({"time":"09:12:44.600","north":4604.566,"east":-1242.064,"vertical":-27.096,
                 "length":4769.223,"course":344.9,"pitch":-0.33,"mode":"R"})"},
            {"$PNVGBLS,145505.20,0.437,0.374,-0.040,0.576,40.61,-4.01,R*1A",
             R"({"time":"14:55:05.200","north":0.437,"east":0.374,"vertical":-0.04,
                 "length":0.576,"course":40.61,"pitch":-4.01,"mode":"R"})"},
            {"$PNVGVOG,140327.80,1.437,5.374,-0.041,R*08",
             R"({"time":"14:03:27.800","vel_north":1.437,"vel_east":5.374,"vel_up":-0.041,
                 "mode":"R"})"},
            {"$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D",
             R"({"params":{"MODE":1,"BASEXYZ":[4268995.2112,721584.9731,4668481.3737]}})"},
            {"$PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040*04",
             R"({"params":{"BASEBLH":[0.8263954319,0.1674465031,467.704]}})"},
            {"$PNVGRTK,BASEXYZ,4268995.2112,721584.9731,4668481.3737*2F",
             R"({"params":{"BASEXYZ":[4268995.2112,721584.9731,4668481.3737]}})"},
            {"$PNVGIDL,MODE,1*7C", R"({"kind":"mode","mode":1})"},
            {"$PNVGIDL,ADD,0003,0.0720*3B", R"({"kind":"add","station_id":3,"icb":0.072})"},
            {"$PNVGIDL,REMOVE,OK*4C", R"({"kind":"remove","ok":true,"status":"OK"})"},
            {"$PNVGIDL,CLEAR,OK*13", R"({"kind":"clear","ok":true,"status":"OK"})"},
            {"$PNVGIDL,4,1,0001,0.0000*54",
             R"({"kind":"item","count":4,"index":1,"station_id":1,"icb":0})"},
            {"$PNVGIDL,4,2,0002,0.0020*56",
             R"({"kind":"item","count":4,"index":2,"station_id":2,"icb":0.002})"},
            {"$PNVGIDL,4,3,0032,0.0000*56",
             R"({"kind":"item","count":4,"index":3,"station_id":32,"icb":0})"},
            {"$PNVGIDL,4,4,0043,0.0720*52",
             R"({"kind":"item","count":4,"index":4,"station_id":43,"icb":0.072})"},
            {"$PNVGTME,128,40327.564756284*49", R"({"counter":128,"tow":40327.564756284})"},
            {"$PNVGTMU,128,081248.547824228*61", R"({"counter":128,"time":"08:12:48.547824228"})"},
            {"$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,403.995,M,47.848,M,2.2,"
             "0002*4D",
             R"({"time":"14:55:05.280","quality":4,"sats_used":17,"hdop":0.7,"alt_msl":403.995,
                 "geoid_sep":47.848,"dgps_age":2.2,"dgps_station":2})"},
            {"$PNVGSDP,151337.40,0.005,0.004,0.009,R*38",
             R"({"time":"15:13:37.400","sd_lat":0.005,"sd_lon":0.004,"sd_height":0.009,
                 "mode":"R"})"},
            {"$PNVGSDV,151337.40,0.087,0.077,0.118,R*31",
             R"({"time":"15:13:37.400","sd_vel_north":0.087,"sd_vel_east":0.077,
                 "sd_vel_up":0.118,"mode":"R"})"},
            {"$PNVGSDH,151337.40,0.978,R*2E",
             R"({"time":"15:13:37.400","sd_heading":0.978,"mode":"R"})"},
            {"$PNVGDOP,121707.80,1.06,0.94,0.59,0.73,0.50,0.41,0.42,R*14",
             R"({"time":"12:17:07.800","gdop":1.06,"pdop":0.94,"hdop":0.59,"vdop":0.73,
                 "tdop":0.5,"ndop":0.41,"edop":0.42,"mode":"R"})"},
    };
    return m;
}

void compareSubset(const QJsonObject &actual, const QJsonObject &expected) {
    for (auto it = expected.begin(); it != expected.end(); ++it) {
        QVERIFY2(actual.contains(it.key()), qPrintable("missing key " + it.key()));
        QCOMPARE(actual.value(it.key()), it.value());
    }
}

QJsonObject parse(const char *json) {
    QJsonParseError e;
    const auto doc = QJsonDocument::fromJson(QByteArray(json), &e);
    if (e.error != QJsonParseError::NoError) qFatal("bad expected JSON: %s", json);
    return doc.object();
}

gnss::DecoderOptions nvsOptions() {
    gnss::DecoderOptions o;
    o.dialect = "nvs";
    return o;
}

} // namespace

class TstNvsExamples : public QObject {
    Q_OBJECT
private slots:
    void everySpecExampleDecodesToTheSpecValues_data();
    void everySpecExampleDecodesToTheSpecValues();
    void everySpecExampleIsCovered();
    void pre15FirmwareSentencesWithoutTimeTagDecode_data();
    void pre15FirmwareSentencesWithoutTimeTagDecode();
    void timeMarkFixCarriesPosition();
    void rtkReplyMixesSetAndQueriedParameters();
    void nvsGgaQualityMeanings();
    void malformedSentencesAreRefusedNotCrashing_data();
    void malformedSentencesAreRefusedNotCrashing();
    void randomFieldsNeverCrashAnyDecoder();
};

void TstNvsExamples::everySpecExampleDecodesToTheSpecValues_data() {
    QTest::addColumn<QString>("sentence");
    QTest::addColumn<QString>("expected");
    const auto examples = gnss::test::loadSpecExamples();
    if (examples.empty()) QSKIP("../shared/specs/examples.tsv not available");
    for (const auto &ex : examples) {
        if (ex.vendor != "nvs") continue;
        const auto it = expectedValues().find(ex.sentence());
        QTest::newRow(ex.sentence().c_str())
                << QString::fromStdString(ex.sentence())
                << QString(it == expectedValues().end() ? "" : it->second);
    }
}

void TstNvsExamples::everySpecExampleDecodesToTheSpecValues() {
    QFETCH(QString, sentence);
    QFETCH(QString, expected);
    QVERIFY2(!expected.isEmpty(), "no expected values for this example: add them to the table");
    const auto d = decodeOne(sentence, nvsOptions());
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.checksum, QString("ok"));
    compareSubset(d.data, parse(expected.toUtf8().constData()));
}

void TstNvsExamples::everySpecExampleIsCovered() {
    const auto examples = gnss::test::loadSpecExamples();
    if (examples.empty()) QSKIP("../shared/specs/examples.tsv not available");
    int nvs = 0;
    for (const auto &ex : examples)
        if (ex.vendor == "nvs") {
            ++nvs;
            QCOMPARE(ex.verdict,
                     std::string("ok")); // all NVS checksums are valid (docs/spec-notes.md)
        }
    QCOMPARE(nvs, static_cast<int>(expectedValues().size()));
}

void TstNvsExamples::pre15FirmwareSentencesWithoutTimeTagDecode_data() {
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("expected");
    QTest::newRow("PNVGBLS without time")
            << "PNVGBLS,0.437,0.374,-0.040,0.576,40.61,-4.01,R"
            << R"({"time":null,"north":0.437,"east":0.374,"vertical":-0.04,"length":0.576,
                  "course":40.61,"pitch":-4.01,"mode":"R"})";
    QTest::newRow("PNVGIMU without time")
            << "PNVGIMU,0.42,0.37,21.84,0.065,0.064,-0.201"
            << R"({"time":null,"roll":0.42,"pitch":0.37,"yaw":21.84,"acc_north":0.065,
                  "acc_east":0.064,"acc_down":-0.201})";
}

void TstNvsExamples::pre15FirmwareSentencesWithoutTimeTagDecode() {
    QFETCH(QString, body);
    QFETCH(QString, expected);
    std::string line = "$" + body.toStdString() + "*";
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02X", gnss::nmeaChecksum(body.toStdString()));
    line += hex;
    const auto d = decodeOne(QString::fromStdString(line), nvsOptions());
    QVERIFY2(d.ok, qPrintable(d.error));
    compareSubset(d.data, parse(expected.toUtf8().constData()));
}

void TstNvsExamples::timeMarkFixCarriesPosition() {
    const auto d = decodeOne("$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,403.995,"
                             "M,47.848,M,2.2,0002*4D",
                             nvsOptions());
    QVERIFY(d.ok);
    QVERIFY(qAbs(d.data["lat"].toDouble() - (47 + 24.5118287 / 60)) < 1e-12);
    QVERIFY(qAbs(d.data["lon"].toDouble() - (9 + 37.6956032 / 60)) < 1e-12);
}

void TstNvsExamples::rtkReplyMixesSetAndQueriedParameters() {
    // Set PVTRATE, query MODE and SNR, NMEA form of BASEBLH (single letters are values).
    const std::string body = "PNVGRTK,PVTRATE,10,MODE,SNR,BASEBLH,5546.1234,N,03739.1234,E,150.5";
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02X", gnss::nmeaChecksum(body));
    const auto d = decodeOne(QString::fromStdString("$" + body + "*" + hex), nvsOptions());
    QVERIFY2(d.ok, qPrintable(d.error));
    compareSubset(d.data["params"].toObject(), parse(R"({"PVTRATE":10,"MODE":null,"SNR":null,
                            "BASEBLH":[5546.1234,"N",3739.1234,"E",150.5]})"));
}

void TstNvsExamples::nvsGgaQualityMeanings() {
    const auto &d = gnss::nvs::dialect();
    QVERIFY(d.ggaQuality);
    QCOMPARE(int(d.ggaQuality(0)), int(gnss::FixType::None));
    QCOMPARE(int(d.ggaQuality(1)), int(gnss::FixType::Fix3D));
    QCOMPARE(int(d.ggaQuality(2)), int(gnss::FixType::Dgnss));
    QCOMPARE(int(d.ggaQuality(4)), int(gnss::FixType::RtkFixed));
    QCOMPARE(int(d.ggaQuality(5)), int(gnss::FixType::RtkFloat));
    QCOMPARE(int(d.ggaQuality(6)), int(gnss::FixType::Estimated));
    // Mode indicators R/F/E of RMC, VTG and the PNVG sentences.
    QCOMPARE(int(gnss::fixTypeFromModeIndicator('R')), int(gnss::FixType::RtkFixed));
    QCOMPARE(int(gnss::fixTypeFromModeIndicator('F')), int(gnss::FixType::RtkFloat));
    QCOMPARE(int(gnss::fixTypeFromModeIndicator('E')), int(gnss::FixType::Estimated));
}

void TstNvsExamples::malformedSentencesAreRefusedNotCrashing_data() {
    QTest::addColumn<QString>("body");
    QTest::newRow("BRS short") << "PNVGBRS,091244.60,1,2";
    QTest::newRow("RTK value first") << "PNVGRTK,1,MODE";
    QTest::newRow("RTK empty") << "PNVGRTK";
    QTest::newRow("IDL unknown") << "PNVGIDL,FOO";
    QTest::newRow("IDL short item") << "PNVGIDL,4,1";
    QTest::newRow("RST bad type") << "PNVGRST,X";
    QTest::newRow("RZB rate missing") << "PNVGRZB,RMC";
    QTest::newRow("DOP bad number") << "PNVGDOP,121707.80,x,0.94,0.59,0.73,0.50,0.41,0.42,R";
    QTest::newRow("VER short") << "PNVGVER,NVS";
}

void TstNvsExamples::malformedSentencesAreRefusedNotCrashing() {
    QFETCH(QString, body);
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02X", gnss::nmeaChecksum(body.toStdString()));
    const auto d = decodeOne("$" + body + "*" + hex, nvsOptions());
    QVERIFY(!d.ok);
    QVERIFY(!d.error.isEmpty());
}

void TstNvsExamples::randomFieldsNeverCrashAnyDecoder() {
    // Fields drawn from what NVS sentences contain (numbers, letters, names, blanks, empties);
    // every decoder must answer with a message or an error, never crash or hang.
    const char *pool[] = {"",      "0",      "1",       "-1",        "4",
                          "0003",  "0.0720", "OK",      "MODE",      "ADD",
                          "SHOW",  "REMOVE", "CLEAR",   "PORT",      "N",
                          "E",     "R",      "x",       "145505.20", "99999999999999999999",
                          "1e308", " 2 ",    "BASEXYZ", "PNVGTST",   "ANT",
                          "ID",    "-0.040"};
    std::mt19937 rng(20170501);
    int decoded = 0, refused = 0;
    for (const auto &rule : gnss::nvs::dialect().rules) {
        for (int n = 0; n < 300; ++n) {
            std::string body(rule.address);
            const int fields = static_cast<int>(rng() % 16);
            for (int f = 0; f < fields; ++f)
                body += "," + std::string(pool[rng() % std::size(pool)]);
            char hex[3];
            std::snprintf(hex, sizeof hex, "%02X", gnss::nmeaChecksum(body));
            const auto d = decodeOne(QString::fromStdString("$" + body + "*" + hex), nvsOptions());
            QVERIFY(d.ok || !d.error.isEmpty());
            (d.ok ? decoded : refused)++;
        }
    }
    QVERIFY(decoded > 0 && refused > 0);
}

QTEST_APPLESS_MAIN(TstNvsExamples)
#include "tst_nvs_examples.moc"
void emptyStationListAnswersShowWithACountOfZero() {
    const auto d = gnss::test::decodeOne(QString::fromStdString(gnss::buildSentence("PNVGIDL,0")));
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.data["count"].toInt(), 0);
    QVERIFY(d.data["station_id"].isNull());
}
