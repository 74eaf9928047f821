// Fault injection: the --faults grammar, and each fault's effect on a receiver's output.
#include "builtin/simulators.h"
#include "sim/faults.h"

#include "core/framer.h"
#include "core/sentence.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;

namespace {

struct Counts {
    int sentences = 0, badChecksum = 0, truncated = 0;
    std::uint64_t skipped = 0;
};

Counts count(const std::string &bytes) {
    Counts c;
    Framer f;
    f.feed(bytes, [&](std::string_view line) {
        Sentence s;
        if (!s.parse(line)) return;
        ++c.sentences;
        if (s.checksum() != ChecksumStatus::Ok) ++c.badChecksum;
    });
    c.truncated = static_cast<int>(f.stats().truncated);
    c.skipped = f.stats().bytesSkipped;
    return c;
}

// A simulated receiver of `dialect` with `faults` (as --faults takes them), from `seed`.
std::unique_ptr<Receiver> faultyReceiver(std::string_view faults, std::string_view dialect = "nmea",
                                         std::uint32_t seed = 1) {
    std::string error;
    SimOptions o;
    o.seed = seed;
    o.faults = *parseFaults(faults, error);
    return makeReceiver(dialect, o);
}

std::string run(const std::string &faults, double seconds, std::string_view dialect = "nmea") {
    auto rx = faultyReceiver(faults, dialect, 9);
    rx->advance(seconds);
    return rx->takeOutput();
}

} // namespace

class TstSimFaults : public QObject {
    Q_OBJECT
private slots:
    void fullSpecParses() {
        std::string error;
        auto f = parseFaults("badcs=0.05,truncate=0.01,binary=0.2,silence=3@10,"
                             "noreply=PNVGRTK+RQUERY,slowreply=800,hangup=30",
                             error);
        QVERIFY2(f, error.c_str());
        QCOMPARE(f->badChecksum, 0.05);
        QCOMPARE(f->truncate, 0.01);
        QCOMPARE(f->binary, 0.2);
        QCOMPARE(f->silenceFor, 3.0);
        QCOMPARE(f->silenceAt, 10.0);
        QCOMPARE(f->noReply.size(), std::size_t(2));
        QVERIFY(f->replySuppressed("GPSGG", "RQUERY"));
        QVERIFY(f->replySuppressed("PNVGRTK", "MODE"));
        QVERIFY(!f->replySuppressed("PNVGCFG", "W"));
        QCOMPARE(f->slowReplyMs, 800.0);
        QCOMPARE(f->hangupAfter, 30.0);
        QVERIFY(f->silentAt(11) && !f->silentAt(9.9) && !f->silentAt(13.1));
        QVERIFY(parseFaults("", error)->any() == false);
    }
    void badSpecsAreRefusedWithTheReason_data() {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("probability > 1") << "badcs=2"
                                         << "badcs";
        QTest::newRow("not a number") << "truncate=x"
                                      << "truncate";
        QTest::newRow("silence without @") << "silence=3"
                                           << "SECONDS@START";
        QTest::newRow("unknown") << "explode=1"
                                 << "unknown fault";
        QTest::newRow("negative hangup") << "hangup=-1"
                                         << "hangup";
        QTest::newRow("empty noreply") << "noreply="
                                       << "noreply";
        QTest::newRow("hangup back at once") << "hangup=2/0"
                                             << "DOWN > 0";
        QTest::newRow("hangup negative down") << "hangup=2/-1"
                                              << "hangup";
        QTest::newRow("hangup no times") << "hangup=2/1x0"
                                         << "count";
        QTest::newRow("hangup count missing") << "hangup=2/1x"
                                              << "count";
        QTest::newRow("empty powercut") << "powercut=+"
                                        << "powercut";
        QTest::newRow("junk of nothing") << "junk=0"
                                         << "junk";
    }
    void badSpecsAreRefusedWithTheReason() {
        QFETCH(QString, spec);
        QFETCH(QString, mentions);
        std::string error;
        QVERIFY(!parseFaults(spec.toStdString(), error));
        QVERIFY2(QString::fromStdString(error).contains(mentions), error.c_str());
    }
    void badChecksumsComeAtTheRequestedRate() {
        const Counts clean = count(run("", 60));
        QCOMPARE(clean.badChecksum, 0);
        const Counts c = count(run("badcs=0.2", 60));
        QVERIFY(c.sentences > 300);
        const double rate = double(c.badChecksum) / c.sentences;
        QVERIFY2(rate > 0.12 && rate < 0.28, QByteArray::number(rate));
    }
    void truncatedLinesAreCutBeforeTheirEnd() {
        const Counts c = count(run("truncate=0.1", 60));
        QVERIFY(c.truncated > 10);
    }
    void binaryNoiseIsValidRtcm3BetweenSentences() {
        const std::string out = run("binary=1", 10);
        const Counts c = count(out);
        QVERIFY(c.skipped > 10 * 20);
        QCOMPARE(c.badChecksum, 0);
        // The first frame checks out: D3, length, CRC-24Q over header and payload.
        const auto at = out.find('\xD3');
        QVERIFY(at != std::string::npos);
        const int len = ((static_cast<unsigned char>(out[at + 1]) & 3) << 8) |
                        static_cast<unsigned char>(out[at + 2]);
        const std::string frame = out.substr(at, 3 + len + 3);
        const std::uint32_t crc =
                (std::uint32_t(static_cast<unsigned char>(frame[3 + len])) << 16) |
                (std::uint32_t(static_cast<unsigned char>(frame[4 + len])) << 8) |
                static_cast<unsigned char>(frame[5 + len]);
        QCOMPARE(crc24q(std::string_view(frame).substr(0, 3 + len)), crc);
        QCOMPARE(crc24q("123456789"), 0xCDE703u); // CRC-24Q check value
    }
    void junkFloodsBetweenWholeSentences() {
        const std::string clean = run("", 10, "nvs");
        const std::string out = run("junk=20000", 10, "nvs");
        const Counts c = count(out), k = count(clean);
        // About 200 kB of junk over 10 s, and every sentence still whole and checking out.
        QVERIFY2(c.skipped > 190'000 && c.skipped < 210'000,
                 QByteArray::number(qulonglong(c.skipped)));
        QCOMPARE(c.sentences, k.sentences);
        QCOMPARE(c.badChecksum, 0);
        QVERIFY(out.size() > clean.size() + 190'000);
    }
    // A hung receiver is deaf too: a command in its silence is not answered, one after it is.
    void silenceAnswersNothing() {
        auto rx = faultyReceiver("silence=3@2", "nvs");
        rx->advance(2.5);
        rx->takeOutput();
        rx->receive("$PNVGVER*4E\r\n");
        rx->advance(1.0);
        QVERIFY(rx->takeOutput().empty());
        rx->advance(2.0); // past the silence
        rx->takeOutput();
        rx->receive("$PNVGVER*4E\r\n");
        rx->advance(1.0);
        QVERIFY(rx->takeOutput().find("PNVGVER") != std::string::npos);
    }
    void silenceStopsOutputForItsDuration() {
        auto rx = faultyReceiver("silence=3@5");
        rx->advance(4.5);
        QVERIFY(!rx->takeOutput().empty());
        rx->advance(3.0); // 4.5 .. 7.5: silent from 5 to 8
        QVERIFY(rx->takeOutput().empty());
        rx->advance(1.0);
        QVERIFY(!rx->takeOutput().empty());
    }
    void hangupFiresAfterItsTime() {
        auto rx = faultyReceiver("hangup=5");
        rx->advance(4.9);
        QVERIFY(!rx->hungUp());
        rx->takeOutput();
        rx->advance(0.2);
        QVERIFY(rx->hungUp());
        rx->advance(5);
        QVERIFY(rx->takeOutput().empty());
    }
    void sameSeedSameFaults() {
        QCOMPARE(run("badcs=0.1,truncate=0.05,binary=0.3", 20),
                 run("badcs=0.1,truncate=0.05,binary=0.3", 20));
    }
};

QTEST_APPLESS_MAIN(TstSimFaults)
#include "tst_sim_faults.moc"
