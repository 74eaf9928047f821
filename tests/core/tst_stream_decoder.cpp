// StreamDecoder: checksum policy, counting, dialect detection, aliases, and surviving any bytes.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "nmea/nmea_messages.h"
#include "nmea/nmea_rules.h"

#include <QTest>
#include <random>

using namespace gnss;

namespace {

// A vendor that makes checksums optional and owns one proprietary sentence.
struct Probe : Message {
    static const MessageType kType;
    Probe() : Message(kType) {}
    void writeJson(JsonWriter &w) const override { w.beginObject().endObject(); }
};
const MessageType Probe::kType{"PTEST"};
bool decodeProbe(const Sentence &, DecodeContext &ctx) {
    Probe p;
    ctx.deliver(p);
    return true;
}
constexpr SentenceRule kVendorRules[] = {{"PTSTA", AddressMatch::Whole, decodeProbe, "probe"}};
const Dialect kVendor{
        .id = "vendor", .displayName = "Vendor", .rules = kVendorRules, .checksumOptional = true};

struct Collected {
    int decoded = 0, failed = 0;
    std::vector<std::string> errors;
};

Collected run(StreamDecoder &dec, const std::string &bytes) {
    Collected c;
    dec.feed(bytes, [&](const SentenceEvent &ev) {
        if (ev.message)
            ++c.decoded;
        else {
            ++c.failed;
            c.errors.emplace_back(ev.error);
        }
    });
    dec.finish();
    return c;
}

} // namespace

class TstStreamDecoder : public QObject {
    Q_OBJECT
private slots:
    void badChecksumIsRejectedUnlessLenient() {
        const DialectRegistry reg = makeBuiltinRegistry();
        const std::string line = "$GPGGA,000008.00,,,,,0,,,,,,,,,*40\r\n";
        StreamDecoder strict(reg);
        auto c = run(strict, line);
        QCOMPARE(c.decoded, 0);
        QCOMPARE(c.errors.front(), std::string("checksum mismatch: sent 40, computed 6C"));
        QCOMPARE(strict.addressStats().front().checksumBad, std::uint64_t(1));
        QCOMPARE(strict.addressStats().front().rejected, std::uint64_t(1));
        StreamDecoder lenient(reg, {.lenient = true});
        QCOMPARE(run(lenient, line).decoded, 1);
        QCOMPARE(lenient.addressStats().front().checksumBad, std::uint64_t(1));
    }

    void missingChecksumIsADialectProperty() {
        const DialectRegistry reg(standardSentenceRules(), {&kVendor, &nmeaDialect()});
        const std::string lines = "$GPGGA,120000,,,,,0,,,,,,,,\r\n$PTSTA,1\r\n";
        StreamDecoder nmea(reg, {.dialect = "nmea"});
        auto c = run(nmea, lines);
        QCOMPARE(c.decoded, 1); // PTSTA: its own dialect makes the checksum optional
        QCOMPARE(c.errors, std::vector<std::string>{"checksum missing"});
        StreamDecoder vendor(reg, {.dialect = "vendor"});
        QCOMPARE(run(vendor, lines).decoded, 2);
    }

    void autoDetectionNamesTheDialectFromItsSentences() {
        const DialectRegistry reg(standardSentenceRules(), {&kVendor, &nmeaDialect()});
        StreamDecoder dec(reg);
        QVERIFY(dec.dialect() == nullptr);
        run(dec, "$GPGGA,120000,,,,,0,,,,,,,,*55\r\n");
        QVERIFY(dec.dialect() == nullptr);
        run(dec, buildSentence("PTSTA,1") + "\r\n");
        QCOMPARE(dec.dialect(), &kVendor);
        // Once known, the vendor's optional checksum applies to standard sentences too.
        QCOMPARE(run(dec, "$GPGGA,120000,,,,,0,,,,,,,,\r\n").decoded, 1);
    }

    void renamedPrefixIsReadThroughAnAlias() {
        const DialectRegistry reg(standardSentenceRules(), {&kVendor, &nmeaDialect()});
        StreamDecoder dec(reg, {.addressAliases = {{"PXYZA", "PTSTA"}}});
        QCOMPARE(run(dec, buildSentence("PXYZA,1") + "\n").decoded, 1);
        QCOMPARE(dec.addressStats().front().address, std::string("PXYZA"));
    }

    void everyLineIsCountedPerAddress() {
        const DialectRegistry reg = makeBuiltinRegistry();
        StreamDecoder dec(reg);
        const std::string data =
                buildSentence("GPGGA,120000,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,") +
                "\r\n" + buildSentence("GPGGA,12x000,,,,,0,,,,,,,,") + "\r\n" +
                buildSentence("PFOO,1") + "\r\n" + "$GPRMC,1\r\n" + "$,\r\n";
        run(dec, data);
        const auto &st = dec.addressStats();
        QCOMPARE(st.size(), std::size_t(4));
        QCOMPARE(st[0].address, std::string("GPGGA"));
        QCOMPARE(st[0].sentences, std::uint64_t(2));
        QCOMPARE(st[0].decoded, std::uint64_t(1));
        QCOMPARE(st[0].decodeErrors, std::uint64_t(1));
        QCOMPARE(st[1].unknown, std::uint64_t(1));
        QCOMPARE(st[2].checksumMissing, std::uint64_t(1));
        QCOMPARE(st[3].address, std::string("(malformed)"));
    }

    void randomBytesNeverCrashTheDecoder() {
        const DialectRegistry reg = makeBuiltinRegistry();
        std::mt19937 rng(1234);
        const std::string valid[] = {
                "$GPGGA,123519.00,4807.038,N,01131.000,E,4,08,0.9,545.4,M,46.9,M,1.2,0031*",
                "$GPGSV,3,2,12,",
                "$GNGSA,A,3,01,02,,,,,,,,,,,1.0,0.5,0.8,1*",
                "$GPRMC,123519,A,4807.038,N,01131.000,E,0,0,230394,,,A*",
                "$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C",
                "$PNVGRTK,MODE,1*",
                "$PNMRX301,1,2,3,4,5,6,7,8,9*",
                "$GPGSV,1,1,04,001,-90,359,99,,,,,,,,,,,,,,,,*"};
        for (bool lenient : {false, true}) {
            StreamDecoder dec(reg, {.lenient = lenient});
            std::uint64_t events = 0;
            for (int round = 0; round < 3000; ++round) {
                std::string chunk;
                const int kind = rng() % 3;
                if (kind == 0) { // pure noise
                    for (int i = 0, n = rng() % 300; i < n; ++i) chunk.push_back(char(rng()));
                } else { // valid sentences with mutated bytes, cut anywhere
                    std::string s = valid[rng() % std::size(valid)];
                    for (int m = 0, n = rng() % 4; m < n; ++m)
                        s[rng() % s.size()] = "0123456789,.-*$AZ\r\n"[rng() % 19];
                    chunk = s.substr(0, rng() % (s.size() + 1)) + (rng() % 2 ? "\r\n" : "");
                }
                dec.feed(chunk, [&](const SentenceEvent &) { ++events; });
            }
            dec.finish();
            QVERIFY2(events > 500, qPrintable(QString::number(events)));
            QCOMPARE(dec.framerStats().bytesIn > 0, true);
        }
    }
};

QTEST_APPLESS_MAIN(TstStreamDecoder)
#include "tst_stream_decoder.moc"
