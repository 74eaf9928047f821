// readFixedDigits: fields printed at fixed widths read at once, and everything else refused (the
// decoders then read field by field).
#include "core/fixed_digits.h"

#include <QTest>

#include <string>
#include <vector>

namespace {
constexpr gnss::DigitLayout kSatellite{"dd,dd,ddd,dd"};
constexpr gnss::DigitLayout kFourIds{"dd,dd,dd,dd"};
constexpr gnss::DigitLayout kSixteen{"dddd,ddd,dd,d,dd"};

// The text in a buffer of its own size, so that a read past its end is caught by ASan.
template <auto L> bool read(const QByteArray &text, std::vector<int> &out) {
    const std::vector<char> exact(text.begin(), text.end());
    int values[8] = {};
    const bool ok = gnss::readFixedDigits<L>(std::string_view(exact.data(), exact.size()), values);
    out.assign(values, values + L.fields);
    return ok;
}
} // namespace

using Values = std::vector<int>;
Q_DECLARE_METATYPE(Values)

class TstFixedDigits : public QObject {
    Q_OBJECT
private slots:
    void layoutsDescribeTheirFields() {
        static_assert(kSatellite.kLength == 12 && kSatellite.fields == 4);
        static_assert(kSatellite.first[2] == 6 && kSatellite.width[2] == 3);
        static_assert(kFourIds.kLength == 11 && kFourIds.fields == 4);
        static_assert(kSixteen.kLength == 16 && kSixteen.fields == 5);
        QCOMPARE(int(kSixteen.width[0]), 4);
    }

    void satellite_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<Values>("values");
        QTest::newRow("receiver form") << QByteArray("01,05,000,31") << true << Values{1, 5, 0, 31};
        QTest::newRow("largest") << QByteArray("99,99,999,99") << true << Values{99, 99, 999, 99};
        QTest::newRow("zeros") << QByteArray("00,00,000,00") << true << Values{0, 0, 0, 0};
        QTest::newRow("blank") << QByteArray(" 1,05,000,31") << false << Values{};
        QTest::newRow("negative elevation") << QByteArray("01,-5,000,31") << false << Values{};
        QTest::newRow("letter last") << QByteArray("01,05,000,3a") << false << Values{};
        QTest::newRow("colon (one past 9)") << QByteArray("01,05,0:0,31") << false << Values{};
        QTest::newRow("slash (one before 0)") << QByteArray("01,05,000,/1") << false << Values{};
        QTest::newRow("8-bit byte") << QByteArray("01,05,0\xB0"
                                                  "0,31")
                                    << false << Values{};
        QTest::newRow("8-bit byte in the second word")
                << QByteArray("01,05,000,3\xB1") << false << Values{};
        QTest::newRow("short") << QByteArray("01,05,000,3") << false << Values{};
        QTest::newRow("long") << QByteArray("01,05,000,311") << false << Values{};
    }
    void satellite() {
        QFETCH(QByteArray, text);
        QFETCH(bool, ok);
        QFETCH(Values, values);
        Values got;
        QCOMPARE(read<kSatellite>(text, got), ok);
        if (ok) QCOMPARE(got, values);
    }

    void fourIds_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<Values>("values");
        QTest::newRow("ids") << QByteArray("01,02,03,04") << true << Values{1, 2, 3, 4};
        QTest::newRow("high ids") << QByteArray("65,88,96,99") << true << Values{65, 88, 96, 99};
        QTest::newRow("empty slot") << QByteArray("01,02,03,") << false << Values{};
        QTest::newRow("three-digit id") << QByteArray("001,02,03,4") << false << Values{};
        QTest::newRow("blank inside") << QByteArray("01,02,0 ,04") << false << Values{};
    }
    void fourIds() {
        QFETCH(QByteArray, text);
        QFETCH(bool, ok);
        QFETCH(Values, values);
        Values got;
        QCOMPARE(read<kFourIds>(text, got), ok);
        if (ok) QCOMPARE(got, values);
    }

    void sixteenBytesUseBothWordsWhole() {
        Values got;
        QVERIFY(read<kSixteen>("2024,359,07,1,42", got));
        QCOMPARE(got, (Values{2024, 359, 7, 1, 42}));
        QVERIFY(!read<kSixteen>("2024,359,07,1,4x", got));
    }
};

QTEST_APPLESS_MAIN(TstFixedDigits)
#include "tst_fixed_digits.moc"
