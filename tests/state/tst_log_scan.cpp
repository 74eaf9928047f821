// scanLog: decoding a log on several threads counts exactly what one decoder reading it front to
// back counts — including dialect detection and epochs cut at a segment boundary.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "log_scan_reference.h"
#include "state/log_scan.h"

#include <QTest>

#include <algorithm>
#include <random>

using namespace gnss;

namespace {

// Odd-sized chunks on purpose: chunking must not matter either.
LogScanResult frontToBack(std::string_view log, const DialectRegistry &reg,
                          const DecoderOptions &o) {
    return gnss::test::scanFrontToBack(log, reg, o, 777);
}

void expectSame(const LogScanResult &a, const LogScanResult &b) {
    QCOMPARE(a.framer.bytesIn, b.framer.bytesIn);
    QCOMPARE(a.framer.bytesSkipped, b.framer.bytesSkipped);
    QCOMPARE(a.framer.sentences, b.framer.sentences);
    QCOMPARE(a.framer.truncated, b.framer.truncated);
    QCOMPARE(a.framer.tooLong, b.framer.tooLong);
    QCOMPARE(a.epochs, b.epochs);
    QCOMPARE(a.dialect, b.dialect);
    QCOMPARE(a.addresses.size(), b.addresses.size());
    for (std::size_t i = 0; i < a.addresses.size(); ++i) {
        QCOMPARE(a.addresses[i].address, b.addresses[i].address);
        QCOMPARE(a.addresses[i].sentences, b.addresses[i].sentences);
        QCOMPARE(a.addresses[i].decoded, b.addresses[i].decoded);
        QCOMPARE(a.addresses[i].decodeErrors, b.addresses[i].decodeErrors);
        QCOMPARE(a.addresses[i].unknown, b.addresses[i].unknown);
        QCOMPARE(a.addresses[i].checksumBad, b.addresses[i].checksumBad);
        QCOMPARE(a.addresses[i].checksumMissing, b.addresses[i].checksumMissing);
        QCOMPARE(a.addresses[i].rejected, b.addresses[i].rejected);
    }
}

// A 1 Hz log with noise, bad checksums, sentences without checksum and, from `vendorFrom`
// on, a vendor sentence that names the dialect.
std::string makeLog(int epochs, int vendorFrom, const std::string &vendorSentence) {
    std::mt19937 rng(99);
    std::string s;
    for (int e = 0; e < epochs; ++e) {
        char t[16];
        std::snprintf(t, sizeof t, "%02d%02d%02d.00", e / 3600 % 24, e / 60 % 60, e % 60);
        s += buildSentence(std::string("GPGGA,") + t +
                           ",4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,") +
             "\r\n";
        s += buildSentence("GPGSV,2,1,05,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45") +
             "\r\n";
        if (e % 5 != 3) s += buildSentence("GPGSV,2,2,05,05,10,010,") + "\r\n";
        s += std::string("$GPRMC,") + t +
             ",A,4807.038,N,01131.000,E,0.1,90.0,230394,,,A\r\n";               // no checksum
        if (e % 7 == 0) s += "$GPGSA,A,3,01,02,03,,,,,,,,,,1.8,0.9,1.5*00\r\n"; // bad checksum
        if (e % 11 == 0) s += "\xD3\x00\x05\x01\x02\x03\x04\x05\x06\x07";       // binary
        if (e >= vendorFrom && e % 4 == 0) s += vendorSentence + "\r\n";
        (void)rng;
    }
    return s;
}

} // namespace

class TstLogScan : public QObject {
    Q_OBJECT
private slots:
    void parallelCountsEqualSequential_data() {
        QTest::addColumn<int>("vendorFrom");
        QTest::addColumn<QString>("vendor");
        QTest::addColumn<QString>("dialect");
        QTest::newRow("plain NMEA") << 100000 << ""
                                    << "auto";
        QTest::newRow("Nemerix named early") << 0 << "$PNMRX600*6F"
                                             << "auto";
        QTest::newRow("Nemerix named late") << 2500 << "$PNMRX600*6F"
                                            << "auto";
        QTest::newRow("NVS named early") << 0 << "$PNVGVER*4E"
                                         << "auto";
        QTest::newRow("GeoStar once at start") << 0 << "$GPSGG,RQUERY*70"
                                               << "auto";
        QTest::newRow("dialect given") << 100000 << ""
                                       << "nemerix";
        QTest::newRow("lenient") << 100000 << ""
                                 << "lenient";
        QTest::newRow("CR line ends") << 100000 << ""
                                      << "CR";
    }
    void parallelCountsEqualSequential() {
        QFETCH(int, vendorFrom);
        QFETCH(QString, vendor);
        QFETCH(QString, dialect);
        const DialectRegistry reg = makeBuiltinRegistry();
        std::string log = makeLog(3000, vendorFrom, vendor.toStdString());
        if (vendor.contains("RQUERY"))
            log = vendor.toStdString() + "\r\n" + makeLog(3000, 100000, "");
        DecoderOptions o;
        if (dialect == "lenient")
            o.lenient = true;
        else if (dialect == "CR") // a log with no LF at all: still cut into segments
            log.erase(std::remove(log.begin(), log.end(), '\n'), log.end());
        else
            o.dialect = dialect.toStdString();
        const LogScanResult seq = frontToBack(log, reg, o);
        QVERIFY(seq.epochs > 2900);
        for (unsigned threads : {1u, 2u, 3u, 7u}) {
            for (unsigned perThread : {1u, 4u, 16u}) {
                const LogScanResult par = scanLog(log, reg, o, threads, 1000, perThread);
                QCOMPARE(par.segments, threads == 1 ? 1u : threads * perThread);
                expectSame(par, seq);
            }
        }
    }

    // Where a line surely ends, reading the bytes alone: a LF, a CR LF, a CR before anything but
    // a LF; a CR that is the last byte may be half of a CR LF still to come.
    void lineEnds_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("after"); // lineEndAfter, -1: none
        QTest::addColumn<int>("last");  // lastLineEnd
        QTest::newRow("LF") << QByteArray("ab\ncd") << 0 << 3 << 3;
        QTest::newRow("CR LF") << QByteArray("ab\r\ncd") << 0 << 4 << 4;
        QTest::newRow("CR alone") << QByteArray("ab\rcd") << 0 << 3 << 3;
        QTest::newRow("CR last") << QByteArray("ab\r") << 0 << -1 << 0;
        QTest::newRow("CR LF then CR last") << QByteArray("a\r\nb\r") << 0 << 3 << 3;
        QTest::newRow("two CRs last") << QByteArray("a\r\r") << 0 << 2 << 2;
        QTest::newRow("from past the first") << QByteArray("a\nb\rc\n") << 2 << 4 << 6;
        QTest::newRow("none") << QByteArray("abc") << 0 << -1 << 0;
        QTest::newRow("empty") << QByteArray() << 0 << -1 << 0;
    }
    void lineEnds() {
        QFETCH(QByteArray, bytes);
        QFETCH(int, from);
        QFETCH(int, after);
        QFETCH(int, last);
        const std::string_view s(bytes.constData(), static_cast<std::size_t>(bytes.size()));
        const std::size_t a = lineEndAfter(s, static_cast<std::size_t>(from));
        QCOMPARE(a == std::string_view::npos ? -1 : static_cast<int>(a), after);
        QCOMPARE(static_cast<int>(lastLineEnd(s)), last);
    }

    // An epoch whose time-carrying sentences are all on one side of a cut, with only GSV on the
    // other side, is one epoch (fuzz_log_scan found it counted twice: a segment without any
    // time gave an epoch of its own).
    void epochCutFromItsTime_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<unsigned>("threads");
        QTest::newRow("GSV before the log's first time") << "head" << 2u;
        QTest::newRow("GSV after the log's last time") << "tail" << 2u;
        QTest::newRow("a middle segment of GSV alone") << "middle" << 3u;
    }
    void epochCutFromItsTime() {
        QFETCH(QString, shape);
        QFETCH(unsigned, threads);
        const std::string gsv =
                buildSentence("GPGSV,2,1,05,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45") +
                "\r\n";
        const std::string rmc =
                buildSentence("GPRMC,120000.00,A,4807.038,N,01131.000,E,0.1,90.0,230394,,,A") +
                "\r\n";
        const std::string gga =
                buildSentence("GPGGA,120000.00,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,") +
                "\r\n";
        std::string many;
        for (int i = 0; i < 60; ++i) many += gsv;
        std::string log;
        if (shape == "head") log = many + rmc;
        if (shape == "tail") log = rmc + many;
        if (shape == "middle") log = gga + many + many + rmc;
        const DialectRegistry reg = makeBuiltinRegistry();
        const DecoderOptions o;
        const LogScanResult seq = frontToBack(log, reg, o);
        QCOMPARE(seq.epochs, std::uint64_t{1});
        const LogScanResult par = scanLog(log, reg, o, threads, 16, 1);
        QCOMPARE(par.segments, threads);
        expectSame(par, seq);
    }
};

QTEST_APPLESS_MAIN(TstLogScan)
#include "tst_log_scan.moc"
