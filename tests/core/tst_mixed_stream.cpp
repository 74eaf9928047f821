// One decoder, one stream, NMEA and RTCM 3 interleaved (a base that talks NMEA to the host and
// sends its corrections on the same port, as u-blox bases do): every sentence decoded, every
// frame found with its type, the frames' bytes not counted as junk and the junk that is there
// counted exactly — whatever the chunk sizes the bytes arrive in. `gnss-cli stats` says the same.
#include "builtin/dialects.h"
#include "cli_run.h"
#include "core/stream_decoder.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_messages.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss;

namespace {

const std::string kGga =
        "$GPGGA,100000.00,5545.0720,N,03737.1042,E,1,08,1.00,151.2,M,14.6,M,,*53\r\n";
const std::string kRmc = "$GPRMC,100000.00,A,5545.0720,N,03737.1042,E,0.0,0.0,150324,,,A*5D\r\n";

std::string stationFrame(unsigned station) {
    rtcm::StationArp a;
    a.station = station;
    a.gps = a.glonass = true;
    a.x = 2846000.1234;
    a.y = 2190000.5678;
    a.z = 5249000.9012;
    return rtcm::encodeStationArp(a);
}

// Frames of a made-up type (1077's number, any payload): binary bytes of every value,
// '$' and line ends among them.
std::string msmLikeFrame(int seed) {
    std::vector<std::uint8_t> payload = {0x43, 0x50}; // 1077
    QRandomGenerator g{quint32(seed)};
    // A '$' in a frame starts a candidate sentence that its next binary byte ends (a line
    // end before one would make a malformed line: real, but not what this test counts).
    for (int i = 0; i < 120; ++i) {
        std::uint8_t b = std::uint8_t(g.bounded(256));
        if (b == '$' || b == '!') b = 0x80;
        payload.push_back(b);
    }
    payload[10] = '$';
    payload[11] = 'G';
    payload[12] = 0x01;
    payload[20] = '\n';
    return rtcm::frame(payload);
}

struct Mixed {
    std::string bytes;
    int sentences = 0;
    std::map<unsigned, int> frames;
    std::uint64_t frameBytes = 0, junk = 0;
};

Mixed mixed(bool withJunk) {
    Mixed m;
    for (int i = 0; i < 40; ++i) {
        m.bytes += kGga;
        m.bytes += kRmc;
        m.sentences += 2;
        const std::string f = i % 10 == 0 ? stationFrame(7) : msmLikeFrame(i);
        m.bytes += f;
        m.frameBytes += f.size();
        ++m.frames[i % 10 == 0 ? 1005u : 1077u];
        if (withJunk && i % 7 == 3) {
            m.bytes += std::string("\x01\x02\xff junk", 9); // no '$', no 0xD3
            m.junk += 9;
        }
    }
    return m;
}

} // namespace

class TstMixedStream : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();

private slots:
    void bothAreFramed_data() {
        QTest::addColumn<int>("chunk"); // 0: random sizes
        QTest::addColumn<bool>("junk");
        for (int c : {1, 7, 64, 4096, 0}) {
            QTest::addRow("chunk %d", c) << c << false;
            QTest::addRow("chunk %d, junk", c) << c << true;
        }
    }
    void bothAreFramed() {
        QFETCH(int, chunk);
        QFETCH(bool, junk);
        const Mixed m = mixed(junk);
        StreamDecoder dec(registry_);
        std::map<unsigned, int> frames;
        dec.setFrameHandler([&](const rtcm::RtcmFrame &f) { ++frames[f.messageNumber()]; });
        int decoded = 0, errors = 0;
        QRandomGenerator g(42);
        for (std::size_t i = 0; i < m.bytes.size();) {
            const std::size_t n = chunk ? std::size_t(chunk) : std::size_t(g.bounded(1, 300));
            dec.feed(std::string_view(m.bytes).substr(i, n), [&](const SentenceEvent &ev) {
                decoded += ev.message != nullptr;
                errors += ev.message == nullptr;
            });
            i += n;
        }
        dec.finish();
        QCOMPARE(decoded, m.sentences);
        QCOMPARE(errors, 0);
        QVERIFY(frames == m.frames);
        QCOMPARE(dec.rtcmStats().frames, std::uint64_t(40));
        QCOMPARE(dec.rtcmStats().bytesInFrames, m.frameBytes);
        QCOMPARE(dec.rtcmTypes().at(1005), std::uint64_t(4));
        QCOMPARE(dec.rtcmTypes().at(1077), std::uint64_t(36));
        QCOMPARE(dec.junkBytes(), m.junk);
    }

    // gnss-cli stats on the same bytes (a file: decoded on every core; standard input: one
    // decoder): sentences, frames per type, junk.
    void statsCountsFramesApart_data() {
        QTest::addColumn<bool>("file");
        QTest::newRow("file") << true;
        QTest::newRow("standard input") << false;
    }
    void statsCountsFramesApart() {
        QFETCH(bool, file);
        const Mixed m = mixed(true);
        QTemporaryDir dir;
        const QString path = dir.filePath("base.log");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(m.bytes.data(), qint64(m.bytes.size()));
        f.close();
        const auto r =
                file ? test::runCli({"stats", "--json", path})
                     : test::runCli({"stats", "--json", "-"}, QByteArray::fromStdString(m.bytes));
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["sentences"].toInt(), m.sentences);
        const QJsonObject rtcm = o["rtcm"].toObject();
        QCOMPARE(rtcm["frames"].toInt(), 40);
        QCOMPARE(rtcm["bytes"].toInteger(), qint64(m.frameBytes));
        QCOMPARE(rtcm["types"].toObject()["1005"].toInt(), 4);
        QCOMPARE(rtcm["types"].toObject()["1077"].toInt(), 36);
        QCOMPARE(o["bytes_junk"].toInteger(), qint64(m.junk));
        const auto text = test::runCli({"stats", path});
        QVERIFY2(text.out.contains("RTCM 3: 40 frames"), text.out.constData());
    }
};

QTEST_GUILESS_MAIN(TstMixedStream)
#include "tst_mixed_stream.moc"
