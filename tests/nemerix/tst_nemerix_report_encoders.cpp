// The encoders of what a VT002 sends (PNMRX300-304, 600, 602, 603): each report line decoded and
// encoded again is the line byte for byte (checksums computed here, independently of the
// library), messages made from engineering units decode back to them, every refusal builds
// nothing and is translatable, a renamed prefix keeps working, and PNMRX603 built from settings
// reads back (extractSettings) as those settings.
//
// The spec prints no example of any of these reports: its only PNMRX600/603 examples
// (examples.tsv) are the requests, checked here against the request encoders. The report lines
// below are in the receiver's form (what the simulated VT002 sends).
#include "builtin/dialects.h"
#include "builtin_registry.h"
#include "core/stream_decoder.h"
#include "examples_table.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_dialect.h"
#include "vendor_refusal_rows.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <type_traits>

using namespace gnss;
using namespace gnss::nemerix;

using gnss::test::builtinRegistry;

namespace {

// Decodes `line` (a renamed prefix read as PNMRX) and hands the message to `use` while its text
// fields are valid; false when it does not decode.
bool withDecoded(const std::string &line, const std::function<void(const Message &)> &use) {
    DecoderOptions o;
    o.dialect = "nemerix";
    o.addressAliases = {{"PXYZW", "PNMRX"}};
    StreamDecoder d(builtinRegistry(), o);
    bool decoded = false;
    d.decodeLine(line, [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        decoded = true;
        use(*ev.message);
    });
    return decoded;
}

// The report encoder of a decoded message.
EncodeResult encodeReport(const Message &m, std::string_view prefix) {
    if (const auto *a = message_cast<Almanac>(m)) return encodeAlmanac(*a, prefix);
    if (const auto *e = message_cast<EphemerisSubframe>(m))
        return encodeEphemerisSubframe(*e, prefix);
    if (const auto *i = message_cast<Ionosphere>(m)) return encodeIonosphere(*i, prefix);
    if (const auto *u = message_cast<UtcParameters>(m)) return encodeUtc(*u, prefix);
    if (const auto *h = message_cast<ConstellationHealth>(m)) return encodeHealth(*h, prefix);
    if (const auto *r = message_cast<SettingsReport>(m)) return encodeSettingsReport(*r, prefix);
    if (m.type == &VersionReport::kSoftwareType || m.type == &VersionReport::kFlashType)
        return encodeVersionReport(static_cast<const VersionReport &>(m), prefix);
    EncodeResult none;
    none.error = "no report encoder for " + std::string(m.type->name);
    return none;
}

// The checksum of "$body*hh", computed here.
QString withChecksum(const QString &body) {
    unsigned x = 0;
    for (QChar c : body) x ^= static_cast<unsigned>(c.toLatin1());
    return "$" + body + "*" + QString::asprintf("%02X", x);
}

const gnss::Dialect &D() {
    return dialect();
}

struct Refused {
    const char *name;
    std::function<EncodeResult()> encode;
    const char *mentions; // what the refusal must name
};

SettingsReport report(int number) {
    SettingsReport m;
    m.number = number;
    return m;
}

// A whole message 0..4, valid, for refusal rows to break one field of.
SettingsReport validReport(int number) {
    SettingsReport m = report(number);
    switch (number) {
    case 0:
        for (std::size_t i = 0; i < 7; ++i) m.sequence[i] = m.delay[i] = 1;
        m.nmrxEnabled = 0;
        m.uartSettings = 0x2580;
        break;
    case 1:
        for (auto &v : m.iono) v = 0;
        m.ionoValid = 1, m.numBlocks = 2, m.tzHours = 0, m.tzMinutes = 0;
        break;
    case 2:
        m.maxPdop = m.maxHdop = 10, m.invalidSv = 0, m.minCno = 25, m.minElevation = 5;
        m.maxTm = m.maxSvForFix = 12;
        break;
    case 3:
        m.acqThreshold1 = 350, m.acqThreshold2 = 300, m.noiseFloor = 600, m.kalmanMode = 1;
        m.defaultAltitude = 0;
        break;
    case 4:
        m.correction = 0, m.datum = 216, m.dx = m.dy = m.dz = m.iflatRaw = m.majorARaw = 0;
        break;
    }
    return m;
}

// The simulated VT002's factory settings, as its store holds them: the schema's defaults and
// the values it seeds where the schema gives none.
std::vector<KeyValue> factorySettings() {
    std::vector<KeyValue> v;
    for (const SettingDef &def : D().settings)
        v.push_back({std::string(def.key), std::string(def.defaultValue)});
    for (auto [k, value] : {std::pair{"nmrx.300", "0"},
                            {"nmrx.301", "0"},
                            {"nmrx.302", "0"},
                            {"nmrx.303", "0"},
                            {"nmrx.304", "0"},
                            {"fix.maxPdop", "10"},
                            {"fix.maxHdop", "10"},
                            {"fix.minSnr", "25"},
                            {"fix.minElevation", "5"},
                            {"fix.noiseFloor", "600"},
                            {"fix.altitude2d", "0"},
                            {"nav.channels", "12"}})
        v.push_back({k, value});
    return v;
}

SettingsReportState simulatedState() {
    SettingsReportState s;
    const std::int64_t iono[] = {0x0C, 0x01, -1, -1, 0x2C, 0x00, -3, -1};
    for (std::size_t i = 0; i < 8; ++i) s.iono[i] = iono[i];
    s.ionoValid = false;
    s.numBlocks = 2;
    s.maxSvForFix = 12;
    s.acqThreshold1 = 350;
    s.acqThreshold2 = 300;
    s.kalmanMode = 1;
    return s;
}

// A refusal row's encoder: `valid` as `change` leaves it, through its report encoder.
template <class M>
std::function<EncodeResult()> encoded(M valid, std::type_identity_t<void (*)(M &)> change) {
    return gnss::test::encodedAfter(
            valid, [](const Message &m) { return encodeReport(m, kPrefix); }, change);
}

// A message whose every raw field is 0 (which it can carry), for a row to break one field of.
template <class M> M zeroed() {
    M m;
    for (auto &v : m.raw) v = 0;
    return m;
}

// A refusal row's encoder: the factory settings as `change` leaves them, through
// encodeSettingsReports.
std::function<EncodeResult()> factoryWith(void (*change)(std::vector<KeyValue> &)) {
    return [=] {
        std::vector<KeyValue> v = factorySettings();
        change(v);
        return encodeSettingsReports(v, simulatedState());
    };
}

} // namespace

class TstNemerixReportEncoders : public QObject {
    Q_OBJECT
private slots:
    void everyReportEncodesBackToItsLine_data();
    void everyReportEncodesBackToItsLine();
    void theSpecsRequestExamplesAreWhatTheQueryEncodersSend();
    void messagesFromEngineeringUnitsDecodeBackToThem();
    void settingsReportMessageDecodesBackFieldForField();
    void factorySettingsReportAsTheSimulatedReceiverSendsThem();
    void settingsReportsReadBackAsTheSettings();
    void statusWordsHoldTheModesAndThePort();
    void invalidInputIsRefused_data();
    void invalidInputIsRefused();
    void renamedPrefixKeepsWorking();
};

void TstNemerixReportEncoders::everyReportEncodesBackToItsLine_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("prefix");
    const char *const pnmrx = "PNMRX";
    const struct {
        const char *name, *line, *prefix;
    } rows[] = {
            {"300 almanac",
             "$PNMRX300,17,2A1F,00,90,F3B5,FF5B,A10D3A,C5E4D4,11F00E,EDCBAA,EDCBAA,7FD,3FF*3C",
             pnmrx},
            {"301 subframe 1", "$PNMRX301,5,1,3FC,00,0,F3,0A4,0E10,00,FFFE,3FFFFD*75", pnmrx},
            {"301 subframe 2",
             "$PNMRX301,5,2,A4,FF80,35A1,1C2B3D4E,FFF0,00A1B2C3,0C3D,A1000000,0E10*49", pnmrx},
            {"301 subframe 3",
             "$PNMRX301,5,3,0010,C0000000,FFE0,26E978D5,1F40,80000001,FFD2F1,A4,1FF0*4F", pnmrx},
            {"301 simulated", "$PNMRX301,1,1,101,00,0,00,041,7242,00,0000,000000*71", pnmrx},
            {"302 with SV id", "$PNMRX302,3,0C,01,FF,FF,2C,00,FD,FF*76", pnmrx},
            {"302 without SV id", "$PNMRX302,0C,01,FF,FF,2C,00,FD,FF*69", pnmrx},
            {"303 every word", "$PNMRX303,1,FFFFFFFF,FFFFF6,12,63,01,89,07,12,00000002,00000000*04",
             pnmrx},
            {"303 GPS words only", "$PNMRX303,9,00000010,000001,12,63,01,89,07,12*7E", pnmrx},
            {"304 health", "$PNMRX304,00,00,3F,00*1B", pnmrx},
            {"600 simulated", "$PNMRX600,VT002,NMRX-SW,2.06.0011,070615*4E", pnmrx},
            {"600 with blanks", "$PNMRX600,NMRX-VT002,2.10,Jan 12 2006*08", pnmrx},
            {"602 flash", "$PNMRX602,FC-1.3*45", pnmrx},
            {"603 message 0", "$PNMRX603,0,1,2,3,4,5,6,7,1,0,3,3,1,1,0,0000001F,00002580*09",
             pnmrx},
            {"603 message 1", "$PNMRX603,1,0C,FF,FE,01,7F,80,FF,00,1,0,-2,30*64", pnmrx},
            {"603 message 1 west", "$PNMRX603,1,0C,01,FF,FF,2C,00,FD,FF,1,2,-2,-30*42", pnmrx},
            {"603 message 2", "$PNMRX603,2,10.0,8.5,00000005,30.0,5.0,16,12*55", pnmrx},
            {"603 message 3", "$PNMRX603,3,1200,1400,600,2,250*6A", pnmrx},
            {"603 message 4 user datum", "$PNMRX603,4,0,500,-2000,-2000,-2000,8257224,8137000*73",
             pnmrx},
            {"603 message 4 WGS 84", "$PNMRX603,4,1,216,0,0,0,0,0*6C", pnmrx},
            {"600 renamed", "$PXYZW600,VT002,NMRX-SW,2.06.0011,070615*4B", "PXYZW"},
            {"603 renamed", "$PXYZW603,3,350,300,600,1,0*68", "PXYZW"},
    };
    for (const auto &r : rows) QTest::newRow(r.name) << r.line << r.prefix;
}

void TstNemerixReportEncoders::everyReportEncodesBackToItsLine() {
    QFETCH(QString, line);
    QFETCH(QString, prefix);
    // The line's checksum is its own (computed here).
    const QString body = line.mid(1, line.lastIndexOf('*') - 1);
    QCOMPARE(withChecksum(body), line);
    EncodeResult r;
    QVERIFY(withDecoded(line.toStdString(),
                        [&](const Message &m) { r = encodeReport(m, prefix.toStdString()); }));
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(r.sentences.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(r.sentences.front()), line);
}

void TstNemerixReportEncoders::theSpecsRequestExamplesAreWhatTheQueryEncodersSend() {
    const auto examples = gnss::test::loadSpecExamples();
    if (examples.empty()) QSKIP("examples.tsv not found (shared folder absent)");
    int seen = 0;
    for (const auto &e : examples) {
        if (e.vendor != "nemerix") continue;
        const bool version = e.printed.starts_with("$PNMRX600");
        const bool settings = e.printed.starts_with("$PNMRX603");
        if (!version && !settings) continue;
        ++seen;
        // The sentence with the checksum examples.tsv computed ("*00" is a placeholder).
        const std::string sentence =
                e.printed.substr(0, e.printed.rfind('*') + 1) + e.computedChecksum;
        const EncodeResult q = version ? encodeVersionQuery() : encodeSettingsQuery();
        QCOMPARE(QString::fromStdString(q.sentences.front()), QString::fromStdString(sentence));
        // It is the request, which no report encoder writes.
        QVERIFY(withDecoded(sentence, [&](const Message &m) {
            QVERIFY(m.type == (version ? &PlainCommand::kVersionQueryType
                                       : &PlainCommand::kSettingsQueryType));
        }));
    }
    QVERIFY(seen >= 2);
    VersionReport empty(VersionReport::kSoftwareType);
    QVERIFY(!encodeVersionReport(empty).ok());
}

void TstNemerixReportEncoders::messagesFromEngineeringUnitsDecodeBackToThem() {
    // Klobuchar coefficients and GPS-UTC parameters in engineering units: the raw words are
    // IS-GPS-200's, and the decoder's values come back within half a step of the scale.
    Ionosphere iono;
    iono.sv = 7;
    const double alpha_beta[] = {1.1176e-8, 7.4506e-9, -5.9605e-8, -5.9605e-8,
                                 90112,     0,         -196608,    -65536};
    for (int i = 0; i < 8; ++i) QVERIFY(iono.setValue(i, alpha_beta[i]).empty());
    EncodeResult r = encodeIonosphere(iono);
    QVERIFY2(r.ok(), r.error.c_str());
    QVERIFY(withDecoded(r.sentences.front(), [&](const Message &m) {
        const auto *back = message_cast<Ionosphere>(m);
        QVERIFY(back);
        QCOMPARE(back->sv, iono.sv);
        for (int i = 0; i < 8; ++i) {
            QCOMPARE(back->raw[i], iono.raw[i]);
            const double step = std::ldexp(1.0, Ionosphere::fields()[i].scale);
            QVERIFY(std::fabs(*back->value(i) - alpha_beta[i]) <= step / 2);
        }
    }));

    UtcParameters utc;
    utc.sv = 3;
    QVERIFY(utc.setValue(UtcParameters::A0, -9.3e-10).empty());
    QVERIFY(utc.setValue(UtcParameters::A1, -8.9e-15).empty());
    QVERIFY(utc.setValue(UtcParameters::DtLs, 18).empty());
    QVERIFY(utc.setValue(UtcParameters::Tot, 405504).empty());
    for (auto f : {UtcParameters::WnT, UtcParameters::WnLsf, UtcParameters::Dn})
        QVERIFY(utc.setValue(f, 7).empty());
    QVERIFY(utc.setValue(UtcParameters::DtLsf, 18).empty());
    r = encodeUtc(utc);
    QVERIFY2(r.ok(), r.error.c_str());
    QVERIFY(withDecoded(r.sentences.front(), [&](const Message &m) {
        const auto *back = message_cast<UtcParameters>(m);
        QVERIFY(back);
        QCOMPARE(back->raw, utc.raw);
        QCOMPARE(*back->value(UtcParameters::Tot), 405504.0);
        QCOMPARE(*back->value(UtcParameters::DtLs), 18.0);
    }));

    // An ephemeris subframe: sqrt(A) and toe as a GPS satellite has them.
    EphemerisSubframe e;
    e.sv = 12;
    e.subframe = 2;
    for (int f = 0; f < 9; ++f) QVERIFY(e.setValue(f, 0).empty());
    QVERIFY(e.setValue(EphemerisSubframe::SqrtA, 5153.7).empty());
    QVERIFY(e.setValue(EphemerisSubframe::Toe, 7200).empty());
    QVERIFY(e.setValue(EphemerisSubframe::M0, -0.25).empty());
    r = encodeEphemerisSubframe(e);
    QVERIFY2(r.ok(), r.error.c_str());
    QVERIFY(withDecoded(r.sentences.front(), [&](const Message &m) {
        const auto *back = message_cast<EphemerisSubframe>(m);
        QVERIFY(back);
        QCOMPARE(back->raw, e.raw);
        QVERIFY(std::fabs(*back->value(EphemerisSubframe::SqrtA) - 5153.7) < 1e-5);
        QCOMPARE(*back->value(EphemerisSubframe::Toe), 7200.0);
        QCOMPARE(*back->value(EphemerisSubframe::M0), -0.25);
    }));

    // The almanac as uploaded and as sent: the inclination relative to i0 = 0.30.
    Almanac a;
    a.sv = 30;
    for (int f = 0; f < Almanac::kFieldCount; ++f)
        QVERIFY(a.setValue(static_cast<Almanac::Field>(f), 0).empty());
    QVERIFY(a.setValue(Almanac::DeltaI, 55.0 / 180 - 0.30).empty());
    QVERIFY(a.setValue(Almanac::SqrtA, 5153.7).empty());
    r = encodeAlmanac(a);
    QVERIFY2(r.ok(), r.error.c_str());
    QVERIFY(withDecoded(r.sentences.front(), [&](const Message &m) {
        const auto *back = message_cast<Almanac>(m);
        QVERIFY(back);
        QCOMPARE(back->raw, a.raw);
        QVERIFY(std::fabs((0.30 + *back->value(Almanac::DeltaI)) * 180 - 55.0) < 1e-3);
    }));
}

void TstNemerixReportEncoders::settingsReportMessageDecodesBackFieldForField() {
    for (int n = 0; n <= 4; ++n) {
        SettingsReport m = validReport(n);
        if (n == 1) m.tzHours = -5, m.tzMinutes = -30;
        if (n == 2) m.maxPdop = 6.5, m.invalidSv = 0x80000001;
        if (n == 4) m.datum = 500, m.dx = -9999, m.iflatRaw = 12000000;
        const EncodeResult r = encodeSettingsReport(m);
        QVERIFY2(r.ok(), r.error.c_str());
        QVERIFY(withDecoded(r.sentences.front(), [&](const Message &decoded) {
            const auto *b = message_cast<SettingsReport>(decoded);
            QVERIFY(b);
            QCOMPARE(b->number, m.number);
            QCOMPARE(b->sequence, m.sequence);
            QCOMPARE(b->delay, m.delay);
            QCOMPARE(b->nmrxEnabled, m.nmrxEnabled);
            QCOMPARE(b->uartSettings, m.uartSettings);
            QCOMPARE(b->iono, m.iono);
            QCOMPARE(b->ionoValid, m.ionoValid);
            QCOMPARE(b->numBlocks, m.numBlocks);
            QCOMPARE(b->tzHours, m.tzHours);
            QCOMPARE(b->tzMinutes, m.tzMinutes);
            QCOMPARE(b->maxPdop, m.maxPdop);
            QCOMPARE(b->maxHdop, m.maxHdop);
            QCOMPARE(b->invalidSv, m.invalidSv);
            QCOMPARE(b->minCno, m.minCno);
            QCOMPARE(b->minElevation, m.minElevation);
            QCOMPARE(b->maxTm, m.maxTm);
            QCOMPARE(b->maxSvForFix, m.maxSvForFix);
            QCOMPARE(b->acqThreshold1, m.acqThreshold1);
            QCOMPARE(b->acqThreshold2, m.acqThreshold2);
            QCOMPARE(b->noiseFloor, m.noiseFloor);
            QCOMPARE(b->kalmanMode, m.kalmanMode);
            QCOMPARE(b->defaultAltitude, m.defaultAltitude);
            QCOMPARE(b->correction, m.correction);
            QCOMPARE(b->datum, m.datum);
            QCOMPARE(b->dx, m.dx);
            QCOMPARE(b->dy, m.dy);
            QCOMPARE(b->dz, m.dz);
            QCOMPARE(b->iflatRaw, m.iflatRaw);
            QCOMPARE(b->majorARaw, m.majorARaw);
        }));
    }
}

void TstNemerixReportEncoders::factorySettingsReportAsTheSimulatedReceiverSendsThem() {
    const EncodeResult r = encodeSettingsReports(factorySettings(), simulatedState());
    QVERIFY2(r.ok(), r.error.c_str());
    const std::vector<std::string> expected = {
            "$PNMRX603,0,1,0,2,3,4,5,0,1,0,3,3,1,1,0,00000000,00002580*7F",
            "$PNMRX603,1,0C,01,FF,FF,2C,00,FD,FF,0,2,0,0*72",
            "$PNMRX603,2,10.0,10.0,00000000,25.0,5.0,12,12*6C",
            "$PNMRX603,3,350,300,600,1,0*6D",
            "$PNMRX603,4,0,216,0,0,0,0,0*6D",
    };
    QCOMPARE(r.sentences, expected);
}

void TstNemerixReportEncoders::settingsReportsReadBackAsTheSettings() {
    std::vector<KeyValue> values = factorySettings();
    const std::vector<KeyValue> changed = {
            {"rate.GGA", "2"},
            {"rate.ZDA", "1"},
            {"output.sequence", "RMC;GGA;ZDA"},
            {"nmrx.301", "2"},
            {"serial.baud", "19200"},
            {"serial.parity", "2"},
            {"fix.timeZone", "-0:30"},
            {"fix.maxPdop", "6.5"},
            {"fix.maxHdop", "4.5"},
            {"fix.minSnr", "35"},
            {"fix.minElevation", "10"},
            {"fix.noiseFloor", "700"},
            {"fix.altitude2d", "250"},
            {"nav.channels", "14"},
            {"datum.correction", "0"},
            {"datum.mapDatum", "500"},
            {"datum.dx", "10"},
            {"datum.dy", "-20"},
            {"datum.dz", "30"},
            {"datum.inverseFlattening", "298.5"},
            {"datum.semiMajorAxis", "6378000"},
    };
    values.insert(values.end(), changed.begin(), changed.end()); // the last value of a key wins
    const EncodeResult r = encodeSettingsReports(values, simulatedState());
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(r.sentences.size(), std::size_t(5));
    std::vector<KeyValue> back;
    for (const std::string &s : r.sentences)
        QVERIFY(withDecoded(s, [&](const Message &m) { D().extractSettings(m, back); }));
    auto readBack = [&](const std::string &key) -> std::string {
        for (auto it = back.rbegin(); it != back.rend(); ++it)
            if (it->key == key) return it->value;
        return "(none)";
    };
    for (const KeyValue &kv : changed) {
        const SettingDef *def = findSetting(D().settings, kv.key);
        QVERIFY(def);
        if (def->access == SettingAccess::WriteOnly) continue;
        const std::string got = readBack(kv.key);
        if (def->type == SettingType::Real || def->type == SettingType::Integer)
            QVERIFY2(std::stod(got) == std::stod(kv.value), (kv.key + " = " + got).c_str());
        else
            QCOMPARE(got, kv.value);
    }
    // Message 0 carries the sequence (places) and the port, in this program's word layout.
    QVERIFY(r.sentences[0].starts_with("$PNMRX603,0,2,0,0,0,1,0,3,2,0,3,3,1,1,1,00000008,"
                                       "00204B00*"));
}

void TstNemerixReportEncoders::statusWordsHoldTheModesAndThePort() {
    const int allNow[] = {1, 1, 1, 1, 1};
    QCOMPARE(nmrxEnabledWord(allNow), std::uint64_t(0x155));
    const int utcOnChange[] = {0, 0, 0, 2, 0};
    QCOMPARE(nmrxEnabledWord(utcOnChange), std::uint64_t(0x80));
    QCOMPARE(uartSettingsWord(9600, 0, 0), std::uint64_t(0x2580));
    QCOMPARE(uartSettingsWord(19200, 2, 0), std::uint64_t(0x204B00));
    QCOMPARE(uartSettingsWord(9600, 0, 1), std::uint64_t(0x1002580));
}

void TstNemerixReportEncoders::invalidInputIsRefused_data() {
    QTest::addColumn<int>("index");
    for (int i = 0; i < 25; ++i) QTest::newRow(QByteArray::number(i)) << i;
}

void TstNemerixReportEncoders::invalidInputIsRefused() {
    static const std::vector<Refused> rows = {
            {"ephemeris SV 33",
             encoded(EphemerisSubframe{}, [](EphemerisSubframe &e) { e.sv = 33, e.subframe = 1; }),
             "sv"},
            {"ephemeris subframe 4",
             encoded(EphemerisSubframe{}, [](EphemerisSubframe &e) { e.sv = 1, e.subframe = 4; }),
             "subframe"},
            {"ephemeris field missing",
             encoded(zeroed<EphemerisSubframe>(),
                     [](EphemerisSubframe &e) {
                         e.sv = 1, e.subframe = 1;
                         e.raw[EphemerisSubframe::Toc].reset();
                     }),
             "toc"},
            {"ephemeris IODC wider than 10 bits",
             encoded(zeroed<EphemerisSubframe>(),
                     [](EphemerisSubframe &e) {
                         e.sv = 1, e.subframe = 1;
                         e.raw[EphemerisSubframe::Iodc] = 0x400;
                     }),
             "iodc"},
            {"ionosphere SV 0", encoded(zeroed<Ionosphere>(), [](Ionosphere &m) { m.sv = 0; }),
             "1..32"},
            {"ionosphere alpha0 of 128",
             encoded(zeroed<Ionosphere>(), [](Ionosphere &m) { m.raw[0] = 128; }), "alpha0"},
            {"ionosphere beta3 missing",
             encoded(zeroed<Ionosphere>(), [](Ionosphere &m) { m.raw[7].reset(); }), "beta3"},
            {"UTC A0 missing",
             encoded(zeroed<UtcParameters>(),
                     [](UtcParameters &m) {
                         m.sv = 1;
                         m.raw[UtcParameters::A0].reset();
                     }),
             "a0"},
            {"UTC leap seconds of 200",
             encoded(zeroed<UtcParameters>(),
                     [](UtcParameters &m) { m.raw[UtcParameters::DtLs] = 200; }),
             "dt_ls"},
            {"health code with a comma",
             encoded(ConstellationHealth{},
                     [](ConstellationHealth &m) { m.codes[m.count++] = "0,0"; }),
             "health code"},
            {"version without fields",
             [] { return encodeVersionReport(VersionReport(VersionReport::kSoftwareType)); },
             "version"},
            {"version with '*'",
             encoded(VersionReport(VersionReport::kFlashType),
                     [](VersionReport &v) { v.fieldsText[v.count++] = "FC*1"; }),
             "'*'"},
            {"settings message 5", [] { return encodeSettingsReport(report(5)); },
             "message number"},
            {"settings message 0 delay of 10",
             encoded(validReport(0), [](SettingsReport &m) { m.delay[2] = 10; }), "message delay"},
            {"settings message 0 without UART word",
             encoded(validReport(0), [](SettingsReport &m) { m.uartSettings.reset(); }),
             "uart_settings"},
            {"settings message 1 zone of 14 h",
             encoded(validReport(1), [](SettingsReport &m) { m.tzHours = 14; }),
             "local zone hours"},
            {"settings message 1 blocks of 16",
             encoded(validReport(1), [](SettingsReport &m) { m.numBlocks = 16; }), "num_blocks"},
            {"settings message 2 PDOP not a number",
             encoded(validReport(2), [](SettingsReport &m) { m.maxPdop = std::nan(""); }),
             "max PDOP"},
            {"settings message 3 Kalman mode of 16",
             encoded(validReport(3), [](SettingsReport &m) { m.kalmanMode = 16; }), "kalman_mode"},
            {"settings message 4 without datum",
             encoded(validReport(4), [](SettingsReport &m) { m.datum.reset(); }), "map datum"},
            {"settings message 4 dx of 9 digits",
             encoded(validReport(4), [](SettingsReport &m) { m.dx = 123456789; }), "dx"},
            {"settings without a rate", factoryWith([](std::vector<KeyValue> &v) {
                 std::erase_if(v, [](const KeyValue &kv) { return kv.key == "rate.VTG"; });
             }),
             "rate.VTG"},
            {"settings with a bad time zone", factoryWith([](std::vector<KeyValue> &v) {
                 v.push_back({"fix.timeZone", "25:00"});
             }),
             "fix.timeZone"},
            {"settings with SNR not a number", factoryWith([](std::vector<KeyValue> &v) {
                 v.push_back({"fix.minSnr", "high"});
             }),
             "fix.minSnr"},
            {"settings report with a bad prefix",
             [] { return encodeSettingsReport(validReport(3), "pnmrx"); }, "prefix"},
    };
    QCOMPARE(int(rows.size()), 25); // the rows of _data
    QFETCH(int, index);
    const Refused &row = rows[static_cast<std::size_t>(index)];
    const EncodeResult r = row.encode();
    QVERIFY2(!r.ok(), row.name);
    QVERIFY(r.sentences.empty());
    QVERIFY2(r.error.find(row.mentions) != std::string::npos,
             (row.name + (": " + r.error)).c_str());
    if (std::string_view(row.mentions) != "prefix")    // checkPrefix's text is not a template yet
        QVERIFY2(r.refusal.form != nullptr, row.name); // the GUI shows it translated
}

void TstNemerixReportEncoders::renamedPrefixKeepsWorking() {
    std::vector<EncodeResult> (*const built)(std::string_view) = [](std::string_view prefix) {
        VersionReport v(VersionReport::kSoftwareType);
        v.fieldsText[v.count++] = "VT002";
        Ionosphere iono;
        for (auto &raw : iono.raw) raw = 1;
        ConstellationHealth h;
        h.codes[h.count++] = "00";
        return std::vector<EncodeResult>{
                encodeVersionReport(v, prefix), encodeIonosphere(iono, prefix),
                encodeHealth(h, prefix), encodeSettingsReport(validReport(2), prefix),
                encodeSettingsReports(factorySettings(), simulatedState(), prefix)};
    };
    const auto plain = built(kPrefix);
    const auto renamed = built("PXYZW");
    for (std::size_t i = 0; i < plain.size(); ++i) {
        QVERIFY2(renamed[i].ok(), renamed[i].error.c_str());
        QCOMPARE(renamed[i].sentences.size(), plain[i].sentences.size());
        for (std::size_t k = 0; k < plain[i].sentences.size(); ++k) {
            const std::string &s = renamed[i].sentences[k];
            QVERIFY(s.starts_with("$PXYZW"));
            QCOMPARE(s, applyPrefix(plain[i].sentences[k], "PXYZW"));
            QVERIFY(withDecoded(s, [](const Message &) {})); // read through the alias
        }
    }
    QVERIFY(!built("P")[0].ok());
}

QTEST_APPLESS_MAIN(TstNemerixReportEncoders)
#include "tst_nemerix_report_encoders.moc"
