// JSON of RTCM messages and of a stream's summary: what `gnss-cli rtcm` prints.
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_stream_decoder.h"
#include "rtcm_test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace gnss::rtcm;
using namespace rtcm_test;

namespace {

const std::string kExample1005 =
        fromHex("D3 00 13 3E D7 D3 02 02 98 0E DE EF 34 B4 BD 62 AC 09 41 98 6F 33 36 0B 98");

std::string jsonOf(const std::string &frame) {
    std::string out;
    gnss::JsonWriter w(out);
    writeRtcmJson(w, decodeFrame(frame));
    return out;
}

QJsonObject objectOf(const std::string &json) {
    QJsonParseError error;
    const auto doc = QJsonDocument::fromJson(QByteArray::fromStdString(json), &error);
    if (error.error != QJsonParseError::NoError) qWarning("%s", json.c_str());
    return doc.object();
}

} // namespace

class TstRtcmJson : public QObject {
    Q_OBJECT
private slots:
    void theExample1005PrintsItsFieldsAsPublished() {
        const std::string json = jsonOf(kExample1005);
        QVERIFY2(json.rfind(R"({"type":1005,"length":19,"station":2003,"itrf_year":0,)", 0) == 0,
                 json.c_str());
        // Printed as the standard's example gives them, not as 1114104.5999000001.
        QVERIFY(json.find(R"("x":1114104.5999,"y":-4850729.7108,"z":3975521.4643)") !=
                std::string::npos);
        const QJsonObject o = objectOf(json);
        QCOMPARE(o["gps"].toBool(), true);
        QCOMPARE(o["glonass"].toBool(), false);
        QVERIFY(std::fabs(o["lat"].toDouble() - 38.8047594304) < 1e-9);
        QVERIFY(std::fabs(o["lon"].toDouble() - -77.0647735998) < 1e-9);
        QVERIFY(std::fabs(o["height"].toDouble() - 114.561) < 1e-3);
        QVERIFY(!o.contains("antenna_height"));
        QVERIFY(!o.contains("error"));
    }

    void msmJsonListsSatellitesAndNamedSignals() {
        MsmHeader h;
        h.system = System::Glonass;
        h.msmType = 7;
        h.station = 12;
        h.gloDayOfWeek = 2;
        h.epochMs = 45000000;
        h.satelliteMask = (std::uint64_t(1) << 63) | (std::uint64_t(1) << 40); // 1 and 24
        h.signalMask = (1u << 30) | (1u << 24) | (1u << 10);                   // 2, 8, 22
        h.cellMask = 0b111011;
        const QJsonObject o = objectOf(jsonOf(encodeMsm(h)));
        QCOMPARE(o["type"].toInt(), 1087);
        QCOMPARE(o["station"].toInt(), 12);
        QCOMPARE(o["system"].toString(), QString("GLONASS"));
        QCOMPARE(o["msm"].toInt(), 7);
        QCOMPARE(o["day_of_week"].toInt(), 2);
        QCOMPARE(o["tod_ms"].toInt(), 45000000);
        QVERIFY(!o.contains("tow_ms"));
        QCOMPARE(o["satellites"].toArray(), (QJsonArray{1, 24}));
        const QJsonArray sigs = o["signals"].toArray();
        QCOMPARE(sigs.size(), 3);
        QCOMPARE(sigs[0].toObject(), (QJsonObject{{"id", 2}, {"name", "1C"}}));
        QCOMPARE(sigs[1].toObject(), (QJsonObject{{"id", 8}, {"name", "2C"}}));
        QCOMPARE(sigs[2].toObject(), (QJsonObject{{"id", 22}})); // no name known
        QCOMPARE(o["cells"].toInt(), 5);
    }

    void qzssMsmJsonAlsoGivesPrns() {
        const MsmHeader h{.system = System::Qzss,
                          .msmType = 4,
                          .satelliteMask = std::uint64_t(1) << 63,
                          .signalMask = 1u << 30,
                          .cellMask = 1};
        const QJsonObject o = objectOf(jsonOf(encodeMsm(h)));
        QCOMPARE(o["tow_ms"].toInt(), 0);
        QCOMPARE(o["satellites"].toArray(), (QJsonArray{1}));
        QCOMPARE(o["prns"].toArray(), (QJsonArray{193}));
    }

    void ephemerisAndBiasJsonCarryWhatTheMessageHas() {
        Ephemeris e;
        e.satellite = 24;
        e.frequencyChannel = -3;
        e.tkSeconds = 3600;
        e.tbMinutes = 75;
        e.health = 0;
        QJsonObject o = objectOf(jsonOf(encodeEphemeris(1020, e)));
        QCOMPARE(o["system"].toString(), QString("GLONASS"));
        QCOMPARE(o["satellite"].toInt(), 24);
        QCOMPARE(o["frequency_channel"].toInt(), -3);
        QCOMPARE(o["tk"].toInt(), 3600);
        QCOMPARE(o["tb_minutes"].toInt(), 75);
        QVERIFY(!o.contains("week"));
        QVERIFY(!o.contains("station"));

        GlonassBiases b;
        b.station = 7;
        b.present = {true, false, true, false};
        b.biases = {1.02, std::nullopt, std::nullopt, std::nullopt};
        o = objectOf(jsonOf(encodeGlonassBiases(b)));
        QCOMPARE(o["signals_mask"].toInt(), 0b1010);
        const QJsonObject biases = o["biases"].toObject();
        QCOMPARE(biases.keys(), (QStringList{"1C", "2C"}));
        QCOMPARE(biases["1C"].toDouble(), 1.02);
        QVERIFY(biases["2C"].isNull()); // in the mask, sent as "not valid"
    }

    void otherMessagesPrintNumberAndLength_data() {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QString>("json");
        QTest::newRow("unknown 4000")
                << QByteArray("\xFA\x00\x01\x02\x03", 5) << "{\"type\":4000,\"length\":5}";
        QTest::newRow("1013 has a station id") << QByteArray("\x3F\x51\x00\x00", 4)
                                               << "{\"type\":1013,\"length\":4,\"station\":256}";
        QTest::newRow("truncated 1004") << QByteArray("\x3E\xC1\x00\x00", 4)
                                        << "{\"type\":1004,\"length\":4,\"station\":256,"
                                           "\"error\":\"truncated in the header\"}";
        QTest::newRow("empty keep-alive")
                << QByteArray()
                << "{\"type\":0,\"length\":0,\"error\":\"empty message (keep-alive frame)\"}";
        QTest::newRow("truncated 1005")
                << QByteArray("\x3E\xD7\xD3\x02", 4)
                << "{\"type\":1005,\"length\":4,\"station\":2003,\"error\":\"truncated\"}";
    }
    void otherMessagesPrintNumberAndLength() {
        QFETCH(QByteArray, payload);
        QFETCH(QString, json);
        const std::vector<std::uint8_t> p(payload.begin(), payload.end());
        QCOMPARE(QString::fromStdString(jsonOf(frame(p))), json);
    }

    void theSummaryCountsFramesGarbageAndTypes() {
        const std::string msm = encodeMsm({.system = System::Gps,
                                           .msmType = 7,
                                           .satelliteMask = std::uint64_t(1) << 60,
                                           .signalMask = 1u << 30,
                                           .cellMask = 1});
        std::string bad = msm;
        bad[10] ^= 1;
        const std::string stream = "junk" + kExample1005 + msm + bad + msm + "$GPGGA\r\n" +
                                   frame(std::vector<std::uint8_t>{0x3E}) +
                                   kExample1005.substr(0, 9);
        RtcmStreamDecoder dec;
        int messages = 0;
        dec.feed(stream, [&](const RtcmMessage &) { ++messages; });
        dec.finish([&](const RtcmMessage &) { ++messages; });
        QCOMPARE(messages, 4);
        std::string out;
        gnss::JsonWriter w(out);
        writeRtcmSummaryJson(w, dec);
        const QJsonObject o = objectOf(out);
        QCOMPARE(o["frames"].toInt(), 4);
        QCOMPARE(o["bytes"].toInt(), int(stream.size()));
        QCOMPARE(o["crc_failures"].toInt(), 1);
        QCOMPARE(o["truncated"].toInt(), 1);
        QCOMPARE(o["decode_errors"].toInt(), 1); // the one-byte payload
        QCOMPARE(o["bytes_skipped"].toInt() + o["bytes_in_frames"].toInt(), int(stream.size()));
        QCOMPARE(o["types"].toObject(), (QJsonObject{{"0", 1}, {"1005", 1}, {"1077", 2}}));
    }
};

QTEST_GUILESS_MAIN(TstRtcmJson)
#include "tst_rtcm_json.moc"
