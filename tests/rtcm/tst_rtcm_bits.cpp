// BitReader and BitWriter: RTCM fields MSB first, signed, sign-magnitude, and what happens at the
// end of a payload.
#include "rtcm/bit_reader.h"
#include "rtcm/bit_writer.h"

#include <QTest>

#include <vector>

using namespace gnss::rtcm;

class TstRtcmBits : public QObject {
    Q_OBJECT
private slots:
    void theFirstFieldsOfThe1005ExampleReadAsPublished() {
        const std::vector<std::uint8_t> bytes = {0x3E, 0xD7, 0xD3};
        BitReader r(bytes);
        QCOMPARE(r.u(12), std::uint64_t(1005));
        QCOMPARE(r.u(12), std::uint64_t(2003));
        QVERIFY(r.ok());
        QCOMPARE(r.bitsLeft(), std::size_t(0));
    }

    void writtenFieldsReadBackAsWritten_data() {
        QTest::addColumn<int>("bits");
        QTest::addColumn<qlonglong>("value");
        QTest::addColumn<bool>("isSigned");
        QTest::newRow("1 bit") << 1 << 1LL << false;
        QTest::newRow("5 bits") << 5 << 21LL << false;
        QTest::newRow("12 bits max") << 12 << 4095LL << false;
        QTest::newRow("30 bits") << 30 << 604799999LL << false;
        QTest::newRow("64 bits") << 64 << -1LL << false; // all ones, read unsigned
        QTest::newRow("int 14 negative") << 14 << -8192LL << true;
        QTest::newRow("int 16 -32768") << 16 << -32768LL << true;
        QTest::newRow("int 22 positive") << 22 << 2097151LL << true;
        QTest::newRow("int 38 most negative") << 38 << -137438953472LL << true;
        QTest::newRow("int 38 most positive") << 38 << 137438953471LL << true;
        QTest::newRow("int 38 -48507297108") << 38 << -48507297108LL << true;
        QTest::newRow("int 64 min") << 64 << std::numeric_limits<qlonglong>::min() << true;
    }
    void writtenFieldsReadBackAsWritten() {
        QFETCH(int, bits);
        QFETCH(qlonglong, value);
        QFETCH(bool, isSigned);
        // Between odd-sized neighbours so no field starts on a byte boundary by luck.
        BitWriter w;
        w.u(5, 3);
        if (isSigned)
            w.s(value, unsigned(bits));
        else
            w.u(static_cast<std::uint64_t>(value), unsigned(bits));
        w.u(1, 1);
        BitReader r(w.bytes());
        QCOMPARE(r.u(3), std::uint64_t(5));
        if (isSigned)
            QCOMPARE(r.s(unsigned(bits)), std::int64_t(value));
        else
            QCOMPARE(r.u(unsigned(bits)), static_cast<std::uint64_t>(value));
        QCOMPARE(r.u(1), std::uint64_t(1));
        QVERIFY(r.ok());
    }

    void signMagnitudeFieldsReadBothSigns_data() {
        QTest::addColumn<uint>("pattern"); // 5 bits
        QTest::addColumn<int>("value");
        QTest::newRow("+3") << 0b00011u << 3;
        QTest::newRow("-3") << 0b10011u << -3;
        QTest::newRow("-15") << 0b11111u << -15;
        QTest::newRow("minus zero is zero") << 0b10000u << 0;
    }
    void signMagnitudeFieldsReadBothSigns() {
        QFETCH(uint, pattern);
        QFETCH(int, value);
        BitWriter w;
        w.u(pattern, 5);
        BitReader r(w.bytes());
        QCOMPARE(r.sm(5), std::int64_t(value));
        BitWriter back;
        back.sm(value, 5);
        if (value != 0) QCOMPARE(unsigned(back.bytes()[0] >> 3), pattern);
    }

    void readingPastTheEndGivesZeroAndSaysSo() {
        const std::vector<std::uint8_t> bytes = {0xFF, 0xFF};
        BitReader r(bytes);
        QCOMPARE(r.u(12), std::uint64_t(0xFFF));
        QVERIFY(r.ok());
        QCOMPARE(r.u(5), std::uint64_t(0)); // only 4 left
        QVERIFY(!r.ok());
        QCOMPARE(r.u(1), std::uint64_t(0)); // stays failed
        QCOMPARE(r.chars(3), std::string());
        QCOMPARE(r.bitsLeft(), std::size_t(0));
    }

    void anEmptyPayloadReadsNothing() {
        BitReader r(std::span<const std::uint8_t>{});
        QVERIFY(!r.has(1));
        QCOMPARE(r.s(38), std::int64_t(0));
        QVERIFY(!r.ok());
    }

    void charactersAreBytes() {
        BitWriter w;
        w.u(1, 4).chars("AB\xE9");
        BitReader r(w.bytes());
        r.skip(4);
        QCOMPARE(r.chars(3), std::string("AB\xE9"));
        QVERIFY(r.ok());
        QCOMPARE(w.bitCount(), std::size_t(28));
        QCOMPARE(w.bytes().size(), std::size_t(4)); // padded to a byte
    }
};

QTEST_GUILESS_MAIN(TstRtcmBits)
#include "tst_rtcm_bits.moc"
