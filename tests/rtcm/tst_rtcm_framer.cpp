// RtcmFramer: RTCM 3 frames out of any byte stream, whatever the chunking and whatever lies
// between frames (garbage, NMEA, corrupted frames); CRC-24Q against known values.
#include "rtcm/crc24q.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_stream_decoder.h"
#include "rtcm_test_support.h"

#include <QTest>

#include <random>

using namespace gnss::rtcm;
using namespace rtcm_test;

namespace {

// The RTCM 1005 example printed in RTCM 10403 (and in many decoders' documentation).
const std::string kExample1005 =
        fromHex("D3 00 13 3E D7 D3 02 02 98 0E DE EF 34 B4 BD 62 AC 09 41 98 6F 33 36 0B 98");
// The zero-length frame some casters send as a keep-alive.
const std::string kEmptyFrame = fromHex("D3 00 00 47 EA 4B");

std::string payloadFrame(std::size_t length, std::uint8_t seed) {
    std::vector<std::uint8_t> p(length);
    for (std::size_t i = 0; i < length; ++i) p[i] = static_cast<std::uint8_t>(seed + i * 7);
    if (length >= 2) { // a message number 4000 + seed, so frames tell themselves apart
        p[0] = static_cast<std::uint8_t>((4000 + seed) >> 4);
        p[1] = static_cast<std::uint8_t>(((4000 + seed) & 0xF) << 4);
    }
    return frame(p);
}

std::string randomBytes(std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::string s(n, '\0');
    for (auto &c : s) c = static_cast<char>(rng() & 0xFF);
    return s;
}

// Frames, garbage (with false 0xD3s), NMEA, corrupted frames, keep-alives: a hard stream.
struct Troubled {
    std::string bytes;
    std::vector<std::string> goodFrames; // in order
};

Troubled troubledStream() {
    std::mt19937 rng(7);
    Troubled t;
    for (int i = 0; i < 300; ++i) {
        const std::string f = payloadFrame(rng() % 300, static_cast<std::uint8_t>(i));
        switch (i % 6) {
        case 0:
            t.bytes += "$GPGGA,123519.00,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
            break;
        case 1: t.bytes += randomBytes(rng() % 100, static_cast<std::uint32_t>(i)); break;
        case 2: { // a corrupted frame first
            std::string bad = payloadFrame(rng() % 200 + 2, static_cast<std::uint8_t>(i + 1));
            bad[3 + rng() % (bad.size() - 3)] ^= 0x10;
            t.bytes += bad;
            break;
        }
        case 3: t.bytes += std::string("\xD3\x00\x40 not a frame", 15); break;
        case 4:
            t.bytes += kEmptyFrame;
            t.goodFrames.push_back(kEmptyFrame);
            break;
        default: break;
        }
        t.bytes += f;
        t.goodFrames.push_back(f);
    }
    return t;
}

void checkCountsAddUp(const RtcmFramerStats &s) {
    QCOMPARE(s.bytesIn, s.bytesInFrames + s.bytesSkipped);
}

} // namespace

class TstRtcmFramer : public QObject {
    Q_OBJECT
private slots:
    void crc24qMatchesKnownValues_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<uint>("crc");
        QTest::newRow("nothing") << QByteArray() << 0u;
        // The catalogue check value of CRC-24/LTE-A, the same algorithm.
        QTest::newRow("check string 123456789") << QByteArray("123456789") << 0xCDE703u;
        QTest::newRow("empty frame header D3 00 00") << QByteArray("\xD3\x00\x00", 3) << 0x47EA4Bu;
        QTest::newRow("RTCM 10403 1005 example header and payload")
                << QByteArray::fromStdString(kExample1005.substr(0, kExample1005.size() - 3))
                << 0x360B98u;
    }
    void crc24qMatchesKnownValues() {
        QFETCH(QByteArray, bytes);
        QFETCH(uint, crc);
        QCOMPARE(crc24q(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                        static_cast<std::size_t>(bytes.size())),
                 std::uint32_t(crc));
    }

    void crc24qCanBeComputedInPieces() {
        const std::string s = "123456789";
        const auto *p = reinterpret_cast<const std::uint8_t *>(s.data());
        QCOMPARE(crc24q(p + 4, 5, crc24q(p, 4)), std::uint32_t(0xCDE703));
    }

    void crc24qAgreesWithTheBitwiseDefinitionAtEveryLength() {
        // The definition, one bit at a time, against the table-driven code (eight bytes a step,
        // then one at a time): every length up to 100 covers every split.
        auto bitwise = [](const std::uint8_t *p, std::size_t n) {
            std::uint32_t crc = 0;
            for (std::size_t i = 0; i < n; ++i) {
                crc ^= std::uint32_t(p[i]) << 16;
                for (int b = 0; b < 8; ++b) {
                    crc <<= 1;
                    if (crc & 0x1000000) crc ^= 0x1864CFB;
                }
            }
            return crc & 0xFFFFFF;
        };
        const std::string data = randomBytes(100, 99);
        const auto *p = reinterpret_cast<const std::uint8_t *>(data.data());
        for (std::size_t n = 0; n <= data.size(); ++n) QCOMPARE(crc24q(p, n), bitwise(p, n));
    }

    void thePublished1005ExampleIsOneGoodFrame() {
        const auto r = frameWhole(kExample1005);
        QCOMPARE(r.frames.size(), std::size_t(1));
        QCOMPARE(r.frames[0], kExample1005);
        QCOMPARE(r.stats.frames, std::uint64_t(1));
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(0));
        QCOMPARE(r.stats.crcFailures, std::uint64_t(0));
        RtcmFramer f;
        unsigned number = 0;
        std::size_t payload = 0;
        f.feed(kExample1005, [&](const RtcmFrame &fr) {
            number = fr.messageNumber();
            payload = fr.payload().size();
        });
        QCOMPARE(number, 1005u);
        QCOMPARE(payload, std::size_t(19));
    }

    void framesComeOutTheSameWhateverTheChunking_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("maxChunk");
        QTest::newRow("one byte at a time") << 0 << 1;
        QTest::newRow("two bytes") << 0 << 2;
        QTest::newRow("random 1-8") << 1 << 8;
        QTest::newRow("random 1-64") << 2 << 64;
        QTest::newRow("random 1-1100 (around a frame's size)") << 3 << 1100;
        QTest::newRow("random 1-5000") << 4 << 5000;
        QTest::newRow("random 1-100000") << 5 << 100000;
    }
    void framesComeOutTheSameWhateverTheChunking() {
        QFETCH(int, seed);
        QFETCH(int, maxChunk);
        const Troubled t = troubledStream();
        const auto whole = frameWhole(t.bytes);
        QCOMPARE(whole.frames, t.goodFrames);
        std::vector<std::size_t> sizes(997);
        std::mt19937 rng(static_cast<std::uint32_t>(seed));
        for (auto &s : sizes) s = maxChunk == 1 ? 1 : 1 + rng() % static_cast<unsigned>(maxChunk);
        if (seed == 0) std::fill(sizes.begin(), sizes.end(), std::size_t(maxChunk));
        const auto chunked = frameInChunks(t.bytes, sizes);
        QCOMPARE(chunked.frames, whole.frames);
        QCOMPARE(chunked.stats.frames, whole.stats.frames);
        QCOMPARE(chunked.stats.bytesSkipped, whole.stats.bytesSkipped);
        QCOMPARE(chunked.stats.crcFailures, whole.stats.crcFailures);
        QCOMPARE(chunked.stats.reservedNonzero, whole.stats.reservedNonzero);
        QCOMPARE(chunked.stats.truncated, whole.stats.truncated);
        checkCountsAddUp(chunked.stats);
    }

    void garbageBetweenFramesIsSkippedAndCounted() {
        const std::string garbage = "garbage without the preamble \x01\x02\x7F\xFF";
        const std::string f = payloadFrame(40, 1);
        const auto r = frameWhole(garbage + f + garbage + f + garbage);
        QCOMPARE(r.frames.size(), std::size_t(2));
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(3 * garbage.size()));
        QCOMPARE(r.stats.crcFailures, std::uint64_t(0));
        checkCountsAddUp(r.stats);
    }

    void aCorruptedFrameDoesNotHideTheNextOne_data() {
        QTest::addColumn<int>("offset"); // byte flipped in the bad frame (from its start)
        QTest::addColumn<int>("xorMask");
        QTest::newRow("payload byte") << 10 << 0x01;
        QTest::newRow("first payload byte") << 3 << 0x80;
        QTest::newRow("CRC byte") << 47 << 0x40;
        QTest::newRow("length made longer") << 2 << 0x10;  // claims 16 more bytes
        QTest::newRow("length made shorter") << 2 << 0x08; // 44 → 36
        QTest::newRow("length made huge") << 1 << 0x03;
    }
    void aCorruptedFrameDoesNotHideTheNextOne() {
        QFETCH(int, offset);
        QFETCH(int, xorMask);
        std::string bad = payloadFrame(44, 1); // 50 bytes in all
        bad[static_cast<std::size_t>(offset)] ^= static_cast<char>(xorMask);
        const std::string good = payloadFrame(30, 2);
        for (const std::string &tail : {std::string(), std::string(2000, 'x')}) {
            const auto r = frameWhole(bad + good + tail);
            QCOMPARE(r.frames.size(), std::size_t(1));
            QCOMPARE(r.frames[0], good);
            QVERIFY(r.stats.crcFailures + r.stats.truncated >= 1);
            checkCountsAddUp(r.stats);
        }
    }

    void aFrameInsideAFalseCandidateIsStillFound() {
        // 0xD3 00 40 claims 64 payload bytes; a real frame starts right after that header.
        const std::string good = payloadFrame(20, 3);
        const std::string s = std::string("\xD3\x00\x40", 3) + good + std::string(60, '\x55');
        const auto r = frameWhole(s);
        QCOMPARE(r.frames.size(), std::size_t(1));
        QCOMPARE(r.frames[0], good);
        QCOMPARE(r.stats.crcFailures, std::uint64_t(1));
        checkCountsAddUp(r.stats);
    }

    void aFalse0xD3InGarbageIsSkipped_data() {
        QTest::addColumn<QByteArray>("garbage");
        QTest::addColumn<int>("crcFailures");
        QTest::addColumn<int>("reservedNonzero");
        QTest::newRow("plausible header, wrong CRC")
                << QByteArray("ab\xD3\x00\x05hello...xyz", 16) << 1 << 0;
        QTest::newRow("reserved bits set") << QByteArray("\xD3\xFF\x10zz", 5) << 0 << 1;
        // each 0xD3 reads the next (0xD3, then the frame's own 0xD3) as nonzero reserved bits
        QTest::newRow("0xD3 0xD3 0xD3") << QByteArray("\xD3\xD3\xD3", 3) << 0 << 3;
        QTest::newRow("0xD3 right before the frame") << QByteArray("\xD3", 1) << 0 << 1;
    }
    void aFalse0xD3InGarbageIsSkipped() {
        QFETCH(QByteArray, garbage);
        QFETCH(int, crcFailures);
        QFETCH(int, reservedNonzero);
        const std::string good = payloadFrame(12, 4);
        const auto r = frameWhole(garbage.toStdString() + good);
        QCOMPARE(r.frames.size(), std::size_t(1));
        QCOMPARE(r.frames[0], good);
        QCOMPARE(r.stats.crcFailures, std::uint64_t(crcFailures));
        QCOMPARE(r.stats.reservedNonzero, std::uint64_t(reservedNonzero));
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(garbage.size()));
    }

    void zeroLengthFramesAreFrames() {
        const auto r = frameWhole(kEmptyFrame + kEmptyFrame + payloadFrame(5, 5) + kEmptyFrame);
        QCOMPARE(r.frames.size(), std::size_t(4));
        QCOMPARE(r.frames[0], kEmptyFrame);
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(0));
        RtcmFramer f;
        std::size_t payload = 99;
        unsigned number = 99;
        f.feed(kEmptyFrame, [&](const RtcmFrame &fr) {
            payload = fr.payload().size();
            number = fr.messageNumber();
        });
        QCOMPARE(payload, std::size_t(0));
        QCOMPARE(number, 0u);
    }

    void theLongestFrameIsFound() {
        const std::string f = payloadFrame(kMaxPayload, 6);
        QCOMPARE(f.size(), kMaxFrame);
        const auto r = frameInChunks("xx" + f + f, {3, 1000, 1, 77});
        QCOMPARE(r.frames.size(), std::size_t(2));
        QCOMPARE(r.frames[1], f);
        QVERIFY(frame(std::vector<std::uint8_t>(kMaxPayload + 1)).empty()); // cannot be framed
    }

    void aTruncatedLastFrameIsCountedNotEmitted_data() {
        QTest::addColumn<int>("keep"); // bytes kept of the last frame
        QTest::newRow("preamble only") << 1;
        QTest::newRow("two header bytes") << 2;
        QTest::newRow("header only") << 3;
        QTest::newRow("half") << 30;
        QTest::newRow("all but the last CRC byte") << 59;
    }
    void aTruncatedLastFrameIsCountedNotEmitted() {
        QFETCH(int, keep);
        const std::string good = payloadFrame(20, 7);
        const std::string last = payloadFrame(54, 8).substr(0, static_cast<std::size_t>(keep));
        for (const auto &sizes : {std::vector<std::size_t>{1}, std::vector<std::size_t>{100000}}) {
            const auto r = frameInChunks(good + last, sizes);
            QCOMPARE(r.frames.size(), std::size_t(1));
            QCOMPARE(r.stats.truncated, std::uint64_t(1));
            QCOMPARE(r.stats.bytesSkipped, std::uint64_t(keep));
            checkCountsAddUp(r.stats);
        }
    }

    void aFrameAfterACutCandidateAtTheEndIsStillFound() {
        // The stream ends 200 bytes into a candidate claiming 1000; a whole frame lies inside.
        const std::string good = payloadFrame(10, 9);
        const std::string s = std::string("\xD3\x03\xE8", 3) + "abc" + good + std::string(150, 'z');
        const auto r = frameWhole(s);
        QCOMPARE(r.frames.size(), std::size_t(1));
        QCOMPARE(r.frames[0], good);
        QCOMPARE(r.stats.truncated, std::uint64_t(1));
        checkCountsAddUp(r.stats);
    }

    void aStreamMixingNmeaAndRtcmGivesEveryFrame() {
        const std::string nmea =
                "$GNGGA,092725.00,4717.11399,N,00833.91590,E,1,08,1.01,499.6,M,48.0,M,,*5B\r\n"
                "$GNRMC,092725.00,A,4717.11437,N,00833.91522,E,0.004,77.52,091202,,,A*7A\r\n";
        std::string s;
        std::vector<std::string> frames;
        for (int i = 0; i < 50; ++i) {
            frames.push_back(
                    payloadFrame(static_cast<std::size_t>(i * 3), static_cast<std::uint8_t>(i)));
            s += nmea + frames.back();
        }
        const auto r = frameInChunks(s, {17, 5, 300});
        QCOMPARE(r.frames, frames);
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(50 * nmea.size()));
        QCOMPARE(r.stats.crcFailures, std::uint64_t(0));
    }

    void resetForgetsHeldBytes() {
        RtcmFramer f;
        int frames = 0;
        const std::string good = payloadFrame(30, 10);
        f.feed(good.substr(0, 10), [&](const RtcmFrame &) { ++frames; });
        QCOMPARE(f.pending(), std::size_t(10));
        f.reset();
        QCOMPARE(f.pending(), std::size_t(0));
        f.feed(good, [&](const RtcmFrame &) { ++frames; });
        QCOMPARE(frames, 1);
    }

    void oneMegabyteOfRandomBytesNeverCrashesAndCountsAddUp_data() {
        QTest::addColumn<uint>("seed");
        QTest::newRow("seed 1") << 1u;
        QTest::newRow("seed 2") << 2u;
        QTest::newRow("seed 3") << 3u;
    }
    void oneMegabyteOfRandomBytesNeverCrashesAndCountsAddUp() {
        QFETCH(uint, seed);
        std::string s = randomBytes(1 << 20, seed);
        // Real frames planted in the noise, and a run of 0xD3 candidates.
        const std::string planted = payloadFrame(100, 11);
        for (std::size_t at = 1000; at + planted.size() < s.size(); at += 99991)
            s.replace(at, planted.size(), planted);
        s.replace(5000, 64, std::string(64, '\xD3'));
        std::vector<std::size_t> sizes(101);
        std::mt19937 rng(seed);
        for (auto &n : sizes) n = 1 + rng() % 70000;
        const auto r = frameInChunks(s, sizes);
        const auto whole = frameWhole(s);
        QCOMPARE(r.frames, whole.frames);
        checkCountsAddUp(r.stats);
        // About 4096 bytes 0xD3, one in 64 followed by six zero reserved bits.
        QVERIFY(r.stats.crcFailures > 30);
        QVERIFY(r.stats.reservedNonzero > 3500);
        std::size_t plantedFound = 0;
        for (const auto &f : r.frames) plantedFound += f == planted;
        QCOMPARE(plantedFound, std::size_t(11));

        // Every frame found (planted or by chance) decodes without trouble.
        RtcmStreamDecoder dec;
        std::uint64_t messages = 0;
        dec.feed(s, [&](const RtcmMessage &) { ++messages; });
        dec.finish([&](const RtcmMessage &) { ++messages; });
        QCOMPARE(messages, dec.framerStats().frames);
        std::uint64_t perType = 0;
        for (const auto &[type, count] : dec.typeCounts()) perType += count;
        QCOMPARE(perType, messages);
    }
};

QTEST_GUILESS_MAIN(TstRtcmFramer)
#include "tst_rtcm_framer.moc"
