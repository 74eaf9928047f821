// decodeMessage on anything: random payloads of every length under every message number it
// knows (and a few it does not) never crash, keep number and length, and print as valid JSON.
#include "rtcm/bit_writer.h"
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_messages.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <random>

using namespace gnss::rtcm;

class TstRtcmDecoder : public QObject {
    Q_OBJECT
private slots:
    void randomPayloadsNeverCrashAndPrintValidJson_data() {
        QTest::addColumn<uint>("number");
        std::vector<unsigned> numbers = {1001, 1002, 1003, 1004, 1005, 1006, 1007, 1008, 1009,
                                         1010, 1011, 1012, 1013, 1019, 1020, 1029, 1033, 1042,
                                         1044, 1045, 1046, 1230, 0,    1070, 1078, 4000, 4095};
        for (unsigned n = 1071; n <= 1137; ++n)
            if (isMsm(n)) numbers.push_back(n);
        for (const unsigned n : numbers) QTest::addRow("%u", n) << n;
    }
    void randomPayloadsNeverCrashAndPrintValidJson() {
        QFETCH(uint, number);
        std::mt19937 rng(number);
        int decoded = 0;
        for (int round = 0; round < 400; ++round) {
            // Short payloads often, long ones sometimes: the interesting edges are short.
            const std::size_t length = round < 64 ? std::size_t(round) : rng() % 1024;
            std::vector<std::uint8_t> p(length);
            for (auto &b : p) b = static_cast<std::uint8_t>(rng());
            if (length >= 2) {
                p[0] = static_cast<std::uint8_t>(number >> 4);
                p[1] = static_cast<std::uint8_t>((number & 0xF) << 4 | (p[1] & 0xF));
            }
            if (isMsm(number) && length > 20 && round % 2 == 0) {
                // Masks with few bits set, so some bodies are the right length and decode.
                for (std::size_t i = 9; i < 21; ++i) p[i] &= static_cast<std::uint8_t>(rng());
            }
            const RtcmMessage m = decodeMessage(p);
            QCOMPARE(m.length, length);
            if (length >= 2) QCOMPARE(m.number, unsigned(number));
            QVERIFY(m.error.empty() || std::holds_alternative<std::monostate>(m.body));
            decoded += !std::holds_alternative<std::monostate>(m.body);
            std::string json;
            gnss::JsonWriter w(json);
            writeRtcmJson(w, m);
            QJsonParseError error;
            const QJsonDocument doc =
                    QJsonDocument::fromJson(QByteArray::fromStdString(json), &error);
            QVERIFY2(error.error == QJsonParseError::NoError, json.c_str());
            QCOMPARE(doc.object()["length"].toInteger(), qint64(length));
        }
        // Fixed-layout messages decode whenever long enough; say so for the ones that should.
        if (number == 1005 || number == 1019 || number == 1230) QVERIFY(decoded > 300);
    }
};

QTEST_GUILESS_MAIN(TstRtcmDecoder)
#include "tst_rtcm_decoder.moc"
