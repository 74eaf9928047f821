// Framer: bytes → sentences, whatever the chunking and whatever lies between sentences.
#include "core/framer.h"

#include <QTest>
#include <random>
#include <string>
#include <vector>

using gnss::Framer;
using gnss::FramerStats;

namespace {

struct Result {
    std::vector<std::string> sentences;
    FramerStats stats;
};

Result frameInChunks(const std::string &data, const std::vector<std::size_t> &chunkSizes) {
    Framer f;
    Result r;
    std::size_t pos = 0, k = 0;
    while (pos < data.size()) {
        const std::size_t n = std::min(chunkSizes[k++ % chunkSizes.size()], data.size() - pos);
        f.feed(std::string_view(data).substr(pos, n),
               [&](std::string_view s) { r.sentences.emplace_back(s); });
        pos += n;
    }
    f.finish();
    r.stats = f.stats();
    return r;
}

Result frameWhole(const std::string &data) {
    return frameInChunks(data, {data.size() + 1});
}

// A stream with every kind of trouble a serial line brings.
std::string troubledStream() {
    std::mt19937 rng(42);
    std::string s = "GNSS receiver v1.0 booting\r\n"; // banner
    for (int i = 0; i < 200; ++i) {
        s += "$GPGGA,123519.00,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
        s += "$GPGSV,1,1,01,05,40,083,46*7F\n";
        s += "!AIVDM,1,1,,A,13aEOK?P00PD2wVMdLDRhgvL289?,0*26\r";
        if (i % 7 == 0) { // RTCM3-like binary frame between sentences
            s += "\xD3\x00\x13";
            for (int b = 0; b < 19; ++b) s.push_back(static_cast<char>(rng() & 0xFF));
        }
        if (i % 11 == 0) s += "$GPRMC,1235";                                 // cut by the next '$'
        if (i % 13 == 0) s += "$GPZDA,12" + std::string(5000, '1') + "\r\n"; // too long
    }
    return s;
}

} // namespace

class TstFramer : public QObject {
    Q_OBJECT
private slots:
    void sentenceEndsAtCrLfLfOrCr_data() {
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("CR LF") << QByteArray("$A,1*00\r\n$B,2*00\r\n")
                               << QStringList{"$A,1*00", "$B,2*00"};
        QTest::newRow("LF") << QByteArray("$A,1*00\n$B,2*00\n")
                            << QStringList{"$A,1*00", "$B,2*00"};
        QTest::newRow("CR") << QByteArray("$A,1*00\r$B,2*00\r")
                            << QStringList{"$A,1*00", "$B,2*00"};
        QTest::newRow("mixed") << QByteArray("$A*00\r\n!B*00\r$C*00\n")
                               << QStringList{"$A*00", "!B*00", "$C*00"};
        QTest::newRow("LF CR is two terminators")
                << QByteArray("$A*00\n\r$B*00\n") << QStringList{"$A*00", "$B*00"};
    }
    void sentenceEndsAtCrLfLfOrCr() {
        QFETCH(QByteArray, input);
        QFETCH(QStringList, expected);
        const auto r = frameWhole(input.toStdString());
        QStringList got;
        for (const auto &s : r.sentences) got << QString::fromStdString(s);
        QCOMPARE(got, expected);
    }

    void chunkingNeverChangesTheSentences() {
        const std::string data = troubledStream();
        const Result whole = frameWhole(data);
        QVERIFY(whole.sentences.size() > 500);
        const std::vector<std::vector<std::size_t>> chunkings = {
                {1}, {2}, {3}, {7, 1, 13}, {64}, {4095, 1, 2}, {1 << 20}};
        for (const auto &c : chunkings) {
            const Result r = frameInChunks(data, c);
            QCOMPARE(r.sentences, whole.sentences);
            QCOMPARE(r.stats.bytesSkipped, whole.stats.bytesSkipped);
            QCOMPARE(r.stats.truncated, whole.stats.truncated);
            QCOMPARE(r.stats.tooLong, whole.stats.tooLong);
            QCOMPARE(r.stats.binaryAborted, whole.stats.binaryAborted);
        }
        std::mt19937 rng(7);
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<std::size_t> sizes;
            for (int i = 0; i < 50; ++i) sizes.push_back(1 + rng() % 300);
            QCOMPARE(frameInChunks(data, sizes).sentences, whole.sentences);
        }
    }

    void bytesBetweenSentencesAreSkippedAndCounted() {
        const auto r = frameWhole("garbage\x01\x02$GPGGA*00\r\nmore$GPRMC*00\n");
        QCOMPARE(r.sentences.size(), std::size_t(2));
        QCOMPARE(r.stats.bytesSkipped, std::uint64_t(9 + 4));
        QCOMPARE(r.stats.sentences, std::uint64_t(2));
    }

    void overlongLineIsDroppedAndFramerResynchronises() {
        std::string data = "$GPGGA," + std::string(Framer::kMaxLine, 'x') + "\r\n$GPRMC,ok*00\r\n";
        const auto r = frameWhole(data);
        QCOMPARE(r.stats.tooLong, std::uint64_t(1));
        QCOMPARE(r.sentences, std::vector<std::string>{"$GPRMC,ok*00"});
        // Exactly kMaxLine bytes is still a sentence.
        std::string limit = "$" + std::string(Framer::kMaxLine - 1, 'y') + "\n";
        QCOMPARE(frameWhole(limit).sentences.size(), std::size_t(1));
    }

    void dollarInsideSentenceStartsNewOneAndCountsTruncated() {
        const auto r = frameWhole("$GPGGA,1234$GPRMC,5678*00\r\n");
        QCOMPARE(r.sentences, std::vector<std::string>{"$GPRMC,5678*00"});
        QCOMPARE(r.stats.truncated, std::uint64_t(1));
    }

    void binaryByteInsideSentenceAbandonsIt() {
        const auto r = frameWhole(std::string("$GPG\xD3\x00\x13xyz$GPRMC*00\n", 20));
        QCOMPARE(r.sentences, std::vector<std::string>{"$GPRMC*00"});
        QCOMPARE(r.stats.binaryAborted, std::uint64_t(1));
    }

    void danglingPartialSentenceIsTruncatedAtFinish() {
        const auto r = frameWhole("$GPGGA*00\n$GPRMC,12");
        QCOMPARE(r.sentences.size(), std::size_t(1));
        QCOMPARE(r.stats.truncated, std::uint64_t(1));
    }

    void everyByteIsAccountedFor() {
        const std::string data = troubledStream();
        const Result r = frameWhole(data);
        std::uint64_t inSentences = 0;
        for (const auto &s : r.sentences) inSentences += s.size();
        // bytes = skipped + sentence bytes + terminators (1 or 2 per sentence)
        const std::uint64_t rest = r.stats.bytesIn - r.stats.bytesSkipped - inSentences;
        QVERIFY(rest >= r.sentences.size() && rest <= 2 * r.sentences.size());
        QCOMPARE(r.stats.bytesIn, std::uint64_t(data.size()));
    }
};

QTEST_APPLESS_MAIN(TstFramer)
#include "tst_framer.moc"
