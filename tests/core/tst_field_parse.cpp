// Field parsers: numbers, coordinates, times and dates, and what they refuse.
#include "core/field_parse.h"

#include <QTest>
#include <cmath>

class TstFieldParse : public QObject {
    Q_OBJECT
private slots:
    void realsParse_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<double>("value");
        QTest::newRow("integer") << "42" << true << 42.0;
        QTest::newRow("decimal") << "0.5" << true << 0.5;
        QTest::newRow("leading zeros") << "00187.646" << true << 187.646;
        QTest::newRow("negative") << "-0.201" << true << -0.201;
        QTest::newRow("plus") << "+3.5" << true << 3.5;
        QTest::newRow("trailing dot") << "5." << true << 5.0;
        QTest::newRow("leading dot") << ".25" << true << 0.25;
        QTest::newRow("many decimals") << "40327.564756284" << true << 40327.564756284;
        QTest::newRow("letters") << "1a" << false << 0.0;
        QTest::newRow("two dots") << "1.2.3" << false << 0.0;
        QTest::newRow("sign only") << "-" << false << 0.0;
        QTest::newRow("dot only") << "." << false << 0.0;
        QTest::newRow("exponent") << "1e5" << false << 0.0;
    }
    void realsParse() {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(double, value);
        double v = 0;
        const std::string t = text.toStdString();
        QCOMPARE(gnss::parseReal(t, v), ok);
        if (ok) QVERIFY(std::abs(v - value) < 1e-12 * std::max(1.0, std::abs(value)));
    }

    void coordinatesParse_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("max");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<double>("degrees");
        QTest::newRow("lat") << "5550.612753" << 90 << true << 55 + 50.612753 / 60;
        QTest::newRow("lon") << "03732.252689" << 180 << true << 37 + 32.252689 / 60;
        QTest::newRow("NVS 7 decimals") << "4724.5118287" << 90 << true << 47 + 24.5118287 / 60;
        QTest::newRow("zero") << "0000.0000" << 90 << true << 0.0;
        QTest::newRow("minutes 60") << "4760.0" << 90 << false << 0.0;
        QTest::newRow("lat 91") << "9100.0" << 90 << false << 0.0;
        QTest::newRow("lon 180") << "18000.000" << 180 << true << 180.0;
        QTest::newRow("negative") << "-4807.038" << 90 << false << 0.0;
    }
    void coordinatesParse() {
        QFETCH(QString, text);
        QFETCH(int, max);
        QFETCH(bool, ok);
        QFETCH(double, degrees);
        double v = 0;
        const std::string t = text.toStdString();
        QCOMPARE(gnss::parseDegreesMinutes(t, max, v), ok);
        if (ok) QVERIFY(std::abs(v - degrees) < 1e-12);
    }

    void timesParse_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("formatted");
        QTest::newRow("centiseconds") << "153556.00" << true << "15:35:56.000";
        QTest::newRow("whole") << "123519" << true << "12:35:19.000";
        QTest::newRow("nanoseconds") << "081248.547824228" << true << "08:12:48.547824228";
        QTest::newRow("leap second") << "235960.00" << true << "23:59:60.000";
        QTest::newRow("hour 24") << "240000" << false << "";
        QTest::newRow("short") << "1234" << false << "";
        QTest::newRow("letters") << "12ab56" << false << "";
    }
    void timesParse() {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(QString, formatted);
        gnss::TimeOfDay t;
        const std::string s = text.toStdString();
        QCOMPARE(gnss::parseTimeOfDay(s, t), ok);
        if (ok) QCOMPARE(QString::fromStdString(t.toString()), formatted);
    }

    // More decimals than a nanosecond has are not invented: the fraction stops at 9 digits.
    void timeDecimalsStopAtNanoseconds() {
        gnss::TimeOfDay t;
        QVERIFY(gnss::parseTimeOfDay("081248.547824228", t));
        QCOMPARE(QString::fromStdString(t.toString(12)), QString("08:12:48.547824228"));
        QCOMPARE(QString::fromStdString(t.toString(2)), QString("08:12:48.547824228"));
        QVERIFY(gnss::parseTimeOfDay("081248.5", t));
        QCOMPARE(QString::fromStdString(t.toString(12)), QString("08:12:48.500000000"));
        // As many decimals as were printed (leading zeros kept), none for a whole second.
        QVERIFY(gnss::parseTimeOfDay("123519.05", t));
        QCOMPARE(QString::fromStdString(t.toString(0)), QString("12:35:19.05"));
        QVERIFY(gnss::parseTimeOfDay("123519", t));
        QCOMPARE(QString::fromStdString(t.toString(0)), QString("12:35:19"));
    }

    void datesParse() {
        gnss::Date d;
        QVERIFY(gnss::parseDateDdMmYy("300518", d));
        QCOMPARE(QString::fromStdString(d.toString()), QString("2018-05-30"));
        QVERIFY(gnss::parseDateDdMmYy("010199", d));
        QCOMPARE(d.year, 1999);
        QVERIFY(!gnss::parseDateDdMmYy("320518", d));
        QVERIFY(!gnss::parseDateDdMmYy("301318", d));
        QVERIFY(!gnss::parseDateDdMmYy("3005", d));
    }

    void hexAndIntegersParse() {
        std::uint64_t h = 0;
        QVERIFY(gnss::parseHex("F7FF8064", h));
        QCOMPARE(h, std::uint64_t(0xF7FF8064));
        QVERIFY(gnss::parseHex("7c", h));
        QVERIFY(!gnss::parseHex("G1", h));
        std::int64_t i = 0;
        QVERIFY(gnss::parseInt("-2", i));
        QCOMPARE(i, std::int64_t(-2));
        QVERIFY(gnss::parseInt("068", i));
        QCOMPARE(i, std::int64_t(68));
        QVERIFY(!gnss::parseInt("1.0", i));
        QVERIFY(!gnss::parseInt("", i));
    }
};

QTEST_APPLESS_MAIN(TstFieldParse)
#include "tst_field_parse.moc"
