// Sentence: checksum, address, talker/type and fields.
#include "builtin/dialects.h"
#include "core/dialect_registry.h"
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nmea/nmea_rules.h"

#include <QTest>

using gnss::ChecksumStatus;
using gnss::Sentence;

Q_DECLARE_METATYPE(gnss::ChecksumStatus)

class TstSentence : public QObject {
    Q_OBJECT
private slots:
    void checksumStatus_data() {
        QTest::addColumn<QString>("line");
        QTest::addColumn<gnss::ChecksumStatus>("status");
        QTest::newRow("upper-case ok") << "$GPGPQ,PNVGTST*21" << ChecksumStatus::Ok;
        QTest::newRow("lower-case ok")
                << "$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7c" << ChecksumStatus::Ok;
        QTest::newRow("wrong") << "$GPGGA,000008.00,,,,,0,,,,,,,,,*40" << ChecksumStatus::Bad;
        QTest::newRow("absent") << "$PNMRX603" << ChecksumStatus::Missing;
        QTest::newRow("placeholder xx") << "$PNMRX603*xx" << ChecksumStatus::Missing;
        QTest::newRow("placeholder XX") << "$PNMRX100,0,4800,0*XX" << ChecksumStatus::Missing;
        QTest::newRow("three digits") << "$GPGGA*123" << ChecksumStatus::Bad;
    }
    void checksumStatus() {
        QFETCH(QString, line);
        QFETCH(gnss::ChecksumStatus, status);
        const std::string l = line.toStdString();
        Sentence s;
        QVERIFY(s.parse(l));
        QCOMPARE(int(s.checksum()), int(status));
    }

    void checksumIsXorOfBody() {
        QCOMPARE(gnss::nmeaChecksum("GPGPQ,PNVGTST"), std::uint8_t(0x21));
        QCOMPARE(gnss::buildSentence("PNVGVER"), std::string("$PNVGVER*4E"));
        QCOMPARE(gnss::buildSentence("GPSGG,RQUERY"), std::string("$GPSGG,RQUERY*70"));
        // Long bodies exercise the word-at-a-time path.
        const std::string body =
                "GPGSV,08,01,32,002,33,059,47,004,-2,000,48,005,34,099,49,009,06,017,40";
        Sentence s;
        const std::string line = "$" + body + "*69";
        QVERIFY(s.parse(line));
        QCOMPARE(int(s.checksum()), int(ChecksumStatus::Ok));
    }

    void addressSplitsIntoTalkerAndType_data() {
        QTest::addColumn<QString>("line");
        QTest::addColumn<QString>("address");
        QTest::addColumn<QString>("talker");
        QTest::addColumn<QString>("type");
        QTest::newRow("standard") << "$GPGGA,1*00"
                                  << "GPGGA"
                                  << "GP"
                                  << "GGA";
        QTest::newRow("GN") << "$GNRMC,1*00"
                            << "GNRMC"
                            << "GN"
                            << "RMC";
        QTest::newRow("proprietary NVS") << "$PNVGRTK,MODE*00"
                                         << "PNVGRTK"
                                         << "P"
                                         << "NVGRTK";
        QTest::newRow("proprietary Nemerix") << "$PNMRX110,0*00"
                                             << "PNMRX110"
                                             << "P"
                                             << "NMRX110";
        QTest::newRow("GeoStar") << "$GPSGG,RQUERY*70"
                                 << "GPSGG"
                                 << "GP"
                                 << "SGG";
        QTest::newRow("numeric talker") << "$12GGA,1*00"
                                        << "12GGA"
                                        << "12"
                                        << "GGA";
        QTest::newRow("no fields") << "$PNVGVER*4E"
                                   << "PNVGVER"
                                   << "P"
                                   << "NVGVER";
        QTest::newRow("AIS") << "!AIVDM,1*00"
                             << "AIVDM"
                             << "AI"
                             << "VDM";
    }
    void addressSplitsIntoTalkerAndType() {
        QFETCH(QString, line);
        QFETCH(QString, address);
        QFETCH(QString, talker);
        QFETCH(QString, type);
        const std::string l = line.toStdString();
        Sentence s;
        QVERIFY(s.parse(l));
        QCOMPARE(QString::fromStdString(std::string(s.address())), address);
        QCOMPARE(QString::fromStdString(std::string(s.talker())), talker);
        QCOMPARE(QString::fromStdString(std::string(s.type())), type);
    }

    void fieldsAreTrimmedAndEmptyFieldsKept() {
        Sentence s;
        QVERIFY(s.parse("$PNMRX103, GSV, 2,GGA, 1,ZDA, 0*04"));
        QCOMPARE(s.fieldCount(), std::size_t(6));
        QCOMPARE(s.field(0), std::string_view("GSV"));
        QCOMPARE(s.field(1), std::string_view("2"));
        QCOMPARE(s.rawField(1), std::string_view(" 2"));
        QCOMPARE(s.field(99), std::string_view());
        QVERIFY(s.parse("$GPGGA,,,*00"));
        QCOMPARE(s.fieldCount(), std::size_t(3));
        QVERIFY(s.field(2).empty());
        // Inner blanks stay: GeoStar's six-character commands.
        QVERIFY(s.parse("$GPSGG,GGA ON*08"));
        QCOMPARE(s.field(0), std::string_view("GGA ON"));
        QCOMPARE(int(s.checksum()), int(ChecksumStatus::Ok));
    }

    void malformedLinesAreRejectedWithAReason() {
        Sentence s;
        QVERIFY(!s.parse("$"));
        QVERIFY(!s.parse("$,1,2*00"));
        QVERIFY(s.error() != nullptr);
        QVERIFY(!s.parse("GPGGA,1"));
        std::string many = "$GPXXX" + std::string(300, ',');
        QVERIFY(!s.parse(many));
        QCOMPARE(std::string(s.error()), std::string("too many fields"));
    }

    void wholeAddressIsMatchedBeforeTalkerAndType() {
        static bool sggDecoded = false;
        static constexpr gnss::SentenceRule rules[] = {
                {"GPSGG", gnss::AddressMatch::Whole,
                 [](const Sentence &, gnss::DecodeContext &) { return sggDecoded = true; }, "test"},
                {"SGG", gnss::AddressMatch::Type,
                 [](const Sentence &, gnss::DecodeContext &) { return false; }, "decoy"}};
        static const gnss::Dialect vendor{.id = "test", .displayName = "Test", .rules = rules};
        gnss::DialectRegistry reg(gnss::standardSentenceRules(), {&vendor});
        auto m = reg.lookup("GPSGG", nullptr);
        QVERIFY(m.rule);
        QVERIFY(m.rule->match == gnss::AddressMatch::Whole);
        QCOMPARE(m.dialect, &vendor);
        QVERIFY(reg.lookup("GLSGG", nullptr).rule->match == gnss::AddressMatch::Type);
        QVERIFY(reg.lookup("GNGGA", nullptr).rule);
        QVERIFY(reg.lookup("GPGPQ", nullptr).rule->match == gnss::AddressMatch::Query);
        QVERIFY(!reg.lookup("PXXXX", nullptr).rule);
    }

    void completeSentenceAddsTheChecksum() {
        std::string err;
        QCOMPARE(gnss::completeSentence("PNVGVER", err), std::string("$PNVGVER*4E"));
        QCOMPARE(gnss::completeSentence("$PNVGVER*00\r\n", err), std::string("$PNVGVER*4E"));
        QCOMPARE(gnss::completeSentence("  $GPSGG,RQUERY ", err), std::string("$GPSGG,RQUERY*70"));
        QVERIFY(gnss::completeSentence("", err).empty());
        QVERIFY(!err.empty());
        QVERIFY(gnss::completeSentence("PNVG\x01", err).empty());
        QVERIFY(gnss::completeSentence(",1,2", err).empty());
    }

    // What a person types for gnss-cli send and the console: refused with the cause before
    // anything is sent, or the sentence to send (its checksum added or checked).
    void typedSentencesAreCheckedBeforeSending_data() {
        QTest::addColumn<QByteArray>("typed");
        QTest::addColumn<bool>("fix");
        QTest::addColumn<QString>("sent");  // empty: refused
        QTest::addColumn<QString>("words"); // in the error, or in the note when fixed
        QTest::newRow("body only") << QByteArray("PNVGVER") << false << "$PNVGVER*4E"
                                   << "";
        QTest::newRow("right checksum") << QByteArray("$PNVGVER*4E") << false << "$PNVGVER*4E"
                                        << "";
        QTest::newRow("right checksum, lower case")
                << QByteArray("$PNVGVER*4e") << false << "$PNVGVER*4E"
                << "";
        QTest::newRow("line end and blanks")
                << QByteArray("  $PNVGVER*4E\r\n") << false << "$PNVGVER*4E"
                << "";
        QTest::newRow("a field with a blank")
                << QByteArray("$GPSGG,GGA ON") << false << "$GPSGG,GGA ON*08"
                << "";
        QTest::newRow("encapsulation") << QByteArray("!AIVDM,1") << false << "!AIVDM,1*4A"
                                       << "";
        QTest::newRow("wrong checksum") << QByteArray("$PNVGVER*00") << false << ""
                                        << "it is *4E";
        QTest::newRow("wrong checksum, fixed") << QByteArray("$PNVGVER*00") << true << "$PNVGVER*4E"
                                               << "replaced by *4E";
        QTest::newRow("checksum not hex") << QByteArray("PNVG*ZZ") << true << ""
                                          << "two hex digits";
        QTest::newRow("checksum of one digit") << QByteArray("PNVGVER*4") << false << ""
                                               << "two hex digits";
        QTest::newRow("lower-case address") << QByteArray("hello world") << false << ""
                                            << "address";
        QTest::newRow("blank in the address") << QByteArray("PNVG VER,1") << false << ""
                                              << "address";
        QTest::newRow("no address") << QByteArray(",1,2") << false << ""
                                    << "no address";
        QTest::newRow("empty") << QByteArray("  ") << false << ""
                               << "empty";
        QTest::newRow("tab") << QByteArray("PNVG\tVER") << false << ""
                             << "does not allow";
        QTest::newRow("eight-bit") << QByteArray("PNVG,\xE9") << false << ""
                                   << "does not allow";
        QTest::newRow("reserved backslash") << QByteArray("PNVG,a\\b") << false << ""
                                            << "reserves";
        QTest::newRow("reserved tilde") << QByteArray("PNVG,~") << false << ""
                                        << "reserves";
        QTest::newRow("a second start") << QByteArray("PNVG,$GPGGA") << false << ""
                                        << "reserves";
    }

    void typedSentencesAreCheckedBeforeSending() {
        QFETCH(QByteArray, typed);
        QFETCH(bool, fix);
        QFETCH(QString, sent);
        QFETCH(QString, words);
        std::string error, note;
        const std::string out = gnss::checkTypedSentence(typed.toStdString(), fix, error, &note);
        QCOMPARE(QString::fromStdString(out), sent);
        const QString said = QString::fromStdString(sent.isEmpty() ? error : note);
        QVERIFY2(words.isEmpty() ? said.isEmpty() : said.contains(words), qPrintable(said));
    }
};

QTEST_APPLESS_MAIN(TstSentence)
#include "tst_sentence.moc"
