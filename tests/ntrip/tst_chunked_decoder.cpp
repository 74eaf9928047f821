// The chunked transfer decoder: well-formed bodies decode whatever the cuts (inside a size line,
// inside RTCM frames, between CR and LF), malformed ones stop with a reason and never crash.
#include "ntrip/chunked_decoder.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_framer.h"

#include <QTest>

#include <random>

using namespace gnss;
using namespace gnss::ntrip;

Q_DECLARE_METATYPE(ChunkedDecoder::Status)

namespace {

struct Decoded {
    std::string out;
    ChunkedDecoder::Status status = ChunkedDecoder::Status::Ok;
    std::string error;
    std::uint64_t chunks = 0;
};

Decoded decode(std::string_view in, const std::vector<std::size_t> &cuts = {}) {
    ChunkedDecoder d;
    Decoded r;
    std::size_t from = 0;
    std::vector<std::size_t> ends = cuts;
    ends.push_back(in.size());
    for (std::size_t c : ends) {
        r.status = d.feed(in.substr(from, c - from), r.out);
        from = c;
    }
    r.error = d.error();
    r.chunks = d.chunks();
    return r;
}

// A base-station stream: 1005, GPS and GLONASS MSM4 headers, 1230 (frames of 25 to 100 bytes).
std::string rtcmStream() {
    rtcm::StationArp arp;
    arp.station = 7;
    arp.gps = arp.glonass = true;
    arp.x = 2845455.0;
    arp.y = 2160465.0;
    arp.z = 5265313.0;
    std::string s = rtcm::encodeStationArp(arp);
    for (int epoch = 0; epoch < 3; ++epoch) {
        rtcm::MsmHeader h;
        h.system = rtcm::System::Gps;
        h.msmType = 4;
        h.station = 7;
        h.epochMs = 468018000u + unsigned(epoch) * 1000u;
        h.satelliteMask = 0xF0F0000000000000ull;
        h.signalMask = 0x40000000u;
        h.cellMask = 0xFF;
        h.multipleMessage = true;
        s += rtcm::encodeMsm(h);
        h.system = rtcm::System::Glonass;
        h.epochMs = 46800000u + unsigned(epoch) * 1000u;
        h.gloDayOfWeek = 5;
        h.multipleMessage = false;
        s += rtcm::encodeMsm(h);
    }
    return s;
}

// `data` as HTTP chunks of the given sizes (cycled): boundaries fall inside frames.
std::string chunked(std::string_view data, const std::vector<std::size_t> &sizes,
                    std::string_view extension = {}) {
    std::string out;
    std::size_t pos = 0, k = 0;
    while (pos < data.size()) {
        const std::size_t n = std::min(sizes[k++ % sizes.size()], data.size() - pos);
        char head[32];
        std::snprintf(head, sizeof head, "%zx", n);
        out += head;
        out += extension;
        out += "\r\n";
        out += data.substr(pos, n);
        out += "\r\n";
        pos += n;
    }
    return out + "0\r\n\r\n";
}

std::vector<std::string> frames(std::string_view bytes, rtcm::RtcmFramerStats *stats = nullptr) {
    rtcm::RtcmFramer f;
    std::vector<std::string> out;
    auto keep = [&](const rtcm::RtcmFrame &fr) {
        out.emplace_back(reinterpret_cast<const char *>(fr.bytes.data()), fr.bytes.size());
    };
    f.feed(bytes, keep);
    f.finish(keep);
    if (stats) *stats = f.stats();
    return out;
}

} // namespace

class TstChunkedDecoder : public QObject {
    Q_OBJECT
private slots:
    void bodiesDecode_data() {
        QTest::addColumn<QByteArray>("encoded");
        QTest::addColumn<QByteArray>("decoded");
        QTest::addColumn<ChunkedDecoder::Status>("status");
        QTest::addColumn<int>("chunks");
        using S = ChunkedDecoder::Status;
        QTest::newRow("two chunks and the last")
                << QByteArray("4\r\nWiki\r\n5\r\npedia\r\n0\r\n\r\n") << QByteArray("Wikipedia")
                << S::Finished << 2;
        QTest::newRow("upper-case hex and leading zeros")
                << QByteArray("000A\r\n0123456789\r\n0\r\n\r\n") << QByteArray("0123456789")
                << S::Finished << 1;
        QTest::newRow("extensions are skipped")
                << QByteArray("3;name=value;x\r\nabc\r\n0;end\r\n\r\n") << QByteArray("abc")
                << S::Finished << 1;
        QTest::newRow("spaces after the size are tolerated")
                << QByteArray("3  \r\nabc\r\n0\r\n\r\n") << QByteArray("abc") << S::Finished << 1;
        QTest::newRow("trailer lines after the last chunk")
                << QByteArray("3\r\nabc\r\n0\r\nX-Checksum: 1\r\nX-More: 2\r\n\r\n")
                << QByteArray("abc") << S::Finished << 1;
        QTest::newRow("bare LF instead of CR LF")
                << QByteArray("3\nabc\n0\n\n") << QByteArray("abc") << S::Finished << 1;
        QTest::newRow("data may hold CR LF and NUL")
                << QByteArray("4\r\n\r\n\0\xd3\r\n0\r\n\r\n", 14) << QByteArray("\r\n\0\xd3", 4)
                << S::Finished << 1;
        QTest::newRow("a stream that goes on")
                << QByteArray("3\r\nabc\r\n2\r\nde") << QByteArray("abcde") << S::Ok << 2;
        QTest::newRow("the end without the final blank line")
                << QByteArray("3\r\nabc\r\n0\r\n") << QByteArray("abc") << S::Finished << 1;
        QTest::newRow("a size that is not hex")
                << QByteArray("3\r\nabc\r\nzz\r\nxx") << QByteArray("abc") << S::Error << 1;
        QTest::newRow("an empty size line")
                << QByteArray("\r\nabc") << QByteArray() << S::Error << 0;
        QTest::newRow("a size too large")
                << QByteArray("123456789\r\n") << QByteArray() << S::Error << 0;
        QTest::newRow("a negative size")
                << QByteArray("-5\r\nabc") << QByteArray() << S::Error << 0;
        QTest::newRow("data longer than its size")
                << QByteArray("3\r\nabcd\r\n0\r\n\r\n") << QByteArray("abc") << S::Error << 1;
        QTest::newRow("CR not followed by LF after a size")
                << QByteArray("3\rabc") << QByteArray() << S::Error << 0;
        QTest::newRow("a stray character after the size")
                << QByteArray("3 x\r\nabc") << QByteArray() << S::Error << 0;
    }
    void bodiesDecode() {
        QFETCH(QByteArray, encoded);
        QFETCH(QByteArray, decoded);
        QFETCH(ChunkedDecoder::Status, status);
        QFETCH(int, chunks);
        const Decoded whole = decode(encoded.toStdString());
        QCOMPARE(QByteArray::fromStdString(whole.out), decoded);
        QCOMPARE(whole.status, status);
        QCOMPARE(int(whole.chunks), chunks);
        QCOMPARE(whole.error.empty(), status != ChunkedDecoder::Status::Error);
        // Byte by byte: the same.
        std::vector<std::size_t> everyByte;
        for (std::size_t i = 1; i < std::size_t(encoded.size()); ++i) everyByte.push_back(i);
        const Decoded bytewise = decode(encoded.toStdString(), everyByte);
        QCOMPARE(bytewise.out, whole.out);
        QCOMPARE(bytewise.status, whole.status);
    }

    void rtcmFramesSurviveACutAtEveryPosition_data() {
        QTest::addColumn<QList<int>>("chunkSizes");
        QTest::newRow("chunks of 7 and 13 bytes") << QList<int>{7, 13};
        QTest::newRow("one byte per chunk") << QList<int>{1};
        QTest::newRow("chunks of 100 bytes") << QList<int>{100};
        QTest::newRow("one chunk") << QList<int>{100000};
    }
    void rtcmFramesSurviveACutAtEveryPosition() {
        // Chunk boundaries inside RTCM frames (the chunk sizes), and TCP segment boundaries at
        // every position of the encoded body, including between each CR and its LF (a second
        // cut one byte after the first).
        QFETCH(QList<int>, chunkSizes);
        const std::string rtcm = rtcmStream();
        std::vector<std::size_t> sizes(chunkSizes.begin(), chunkSizes.end());
        const std::string body = chunked(rtcm, sizes, chunkSizes.size() == 2 ? ";x=1" : "");
        const std::vector<std::string> expected = frames(rtcm);
        QCOMPARE(int(expected.size()), 7);
        for (std::size_t cut = 1; cut < body.size(); ++cut) {
            for (std::size_t second : {cut + 1, cut + 2}) {
                const Decoded d =
                        second < body.size() ? decode(body, {cut, second}) : decode(body, {cut});
                QCOMPARE(d.status, ChunkedDecoder::Status::Finished);
                if (d.out != rtcm) QFAIL(qPrintable(QString("cut at %1: bytes differ").arg(cut)));
                rtcm::RtcmFramerStats stats;
                const auto got = frames(d.out, &stats);
                QCOMPARE(got, expected);
                QCOMPARE(stats.crcFailures, std::uint64_t(0));
                QCOMPARE(stats.bytesSkipped, std::uint64_t(0));
            }
        }
    }

    void bytesAfterTheLastChunkAreCountedNotDecoded() {
        ChunkedDecoder d;
        std::string out;
        QCOMPARE(d.feed("2\r\nab\r\n0\r\n\r\nextra", out), ChunkedDecoder::Status::Finished);
        QCOMPARE(out, std::string("ab"));
        QCOMPARE(d.bytesAfterEnd(), std::uint64_t(5));
    }

    void nothingIsDecodedAfterAnError() {
        ChunkedDecoder d;
        std::string out;
        QCOMPARE(d.feed("q\r\n", out), ChunkedDecoder::Status::Error);
        QCOMPARE(d.feed("3\r\nabc\r\n", out), ChunkedDecoder::Status::Error);
        QVERIFY(out.empty());
        QVERIFY2(d.error().find("not hexadecimal") != std::string::npos, d.error().c_str());
        QVERIFY2(d.error().find("'q'") != std::string::npos, d.error().c_str());
    }

    void randomInputNeverCrashesAndDoesNotDependOnCuts() {
        std::mt19937 rng(11);
        for (int i = 0; i < 5000; ++i) {
            std::string in;
            const int n = int(rng() % 200);
            for (int k = 0; k < n; ++k) {
                const char pick = "0123456789abcdefAF\r\n;x "[rng() % 24];
                in.push_back(rng() % 4 ? pick : char(rng() & 0xFF));
            }
            std::vector<std::size_t> cuts;
            for (std::size_t c = 1; c < in.size(); c += 1 + rng() % 9) cuts.push_back(c);
            const Decoded a = decode(in), b = decode(in, cuts);
            QCOMPARE(a.out, b.out);
            QCOMPARE(a.status, b.status);
        }
    }
};

QTEST_APPLESS_MAIN(TstChunkedDecoder)
#include "tst_chunked_decoder.moc"
