// The encoders of what the NV08C-RTK sends (nvs_encoders.h, "What the receiver sends"): each
// spec example is rebuilt byte for byte from its decoding, encode(decode(line)) == line; the
// sentences the spec prints no example of (their examples were images) go the other way round,
// decode(encode(message)) == message field for field; and a value no receiver prints is refused
// with a translatable reason, never printed.
#include "builtin/dialects.h"
#include "core/sentence.h"
#include "core/stream_decoder.h"
#include "decode_helper.h"
#include "examples_table.h"
#include "nvs/nvs_encoders.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <limits>
#include <map>

using namespace gnss;
using namespace gnss::nvs;
using gnss::test::decodeWith;

namespace {

// PNVGNME's default position decimals (4.2), which the spec's PNVGTMC example is printed with.
constexpr int kPositionDecimals = 7;

// The output encoder of a decoded message's type.
EncodeResult encodeMessage(const Message &m) {
    if (const auto *x = message_cast<Ver>(m)) return encodeVer(*x);
    if (const auto *x = message_cast<Bss>(m)) return encodeBss(*x);
    if (const auto *x = message_cast<Tst>(m)) return encodeTst(*x);
    if (const auto *x = message_cast<Imu>(m)) return encodeImu(*x);
    if (const auto *x = message_cast<Brs>(m)) return encodeBrs(*x);
    if (const auto *x = message_cast<Bls>(m)) return encodeBls(*x);
    if (const auto *x = message_cast<Vog>(m)) return encodeVog(*x);
    if (const auto *x = message_cast<Idl>(m)) return encodeIdl(*x);
    if (const auto *x = message_cast<Tme>(m)) return encodeTme(*x);
    if (const auto *x = message_cast<Tmu>(m)) return encodeTmu(*x);
    if (const auto *x = message_cast<Tmc>(m)) return encodeTmc(*x, kPositionDecimals);
    if (const auto *x = message_cast<Sdp>(m)) return encodeSdp(*x);
    if (const auto *x = message_cast<Sdv>(m)) return encodeSdv(*x);
    if (const auto *x = message_cast<Sdh>(m)) return encodeSdh(*x);
    if (const auto *x = message_cast<Dop>(m)) return encodeDop(*x);
    EncodeResult none;
    none.refuse(Refusal("no output encoder for " + std::string(m.type->name)));
    return none;
}

bool hasOutputEncoder(std::string_view address) {
    for (std::string_view a :
         {"PNVGVER", "PNVGBSS", "PNVGTST", "PNVGIMU", "PNVGBRS", "PNVGBLS", "PNVGVOG", "PNVGIDL",
          "PNVGTME", "PNVGTMU", "PNVGTMC", "PNVGSDP", "PNVGSDV", "PNVGSDH", "PNVGDOP"})
        if (a == address) return true;
    return false;
}

std::string json(const Message &m) {
    std::string out;
    JsonWriter w(out);
    m.writeJson(w);
    return out;
}

// encode(decode(line)) == line, byte for byte.
void rebuildsByteForByte(const std::string &line) {
    decodeWith("nvs", line, [&](const Message &m) {
        const EncodeResult r = encodeMessage(m);
        QVERIFY2(r.ok(), r.error.c_str());
        QCOMPARE(r.sentences.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(r.sentences.front()), QString::fromStdString(line));
    });
}

TimeOfDay at(int h, int m, double s, int decimals) {
    TimeOfDay t;
    t.nanos = std::llround(((h * 60LL + m) * 60 + s) * 1e9);
    t.decimals = static_cast<std::uint8_t>(decimals);
    return t;
}

// Messages the spec prints no example of, by row name: what the simulated receiver sends.
using Build = std::function<EncodeResult()>;

// A row: the message of type M as `fill` leaves it, through its own encoder (encodeMessage).
template <class M> Build built(void (*fill)(M &)) {
    return [fill] {
        M m;
        fill(m);
        return encodeMessage(m);
    };
}

// A PNVGIDL SHOW item (4.15): the index-th of count, a station and its GLONASS ICB.
Build idlItem(int count, int index, int stationId, double icb) {
    return [=] {
        Idl m;
        m.kind = IdlKind::Item, m.count = count, m.index = index, m.stationId = stationId,
        m.icb = icb;
        return encodeIdl(m);
    };
}

const std::map<std::string, Build> &withoutExample() {
    static const std::map<std::string, Build> rows = {
            {"4.1 VER reply", built<Ver>([](Ver &m) {
                 m.manufacturer = "NVS", m.device = "RTA", m.rtkFw = "0029", m.csmHw = "CSM24",
                 m.csmFw = "0101";
             })},
            {"4.6 BSS", built<Bss>([](Bss &m) {
                 m.rtcmTotal = 128, m.rtcmErrors = 1, m.rtcmOk = 127, m.baseDistance = 4769.223,
                 m.rtcmAge = 0.6;
             })},
            {"4.6 BSS before any RTCM",
             built<Bss>([](Bss &m) { m.rtcmTotal = m.rtcmErrors = m.rtcmOk = 0; })},
            {"4.7 TST", built<Tst>([](Tst &m) {
                 m.tests = {{"ID", "1254367"}, {"ANT", "0"}};
             })},
            {"4.10 IMU before 1.5 (no time)", built<Imu>([](Imu &m) {
                 m.roll = 0.42, m.pitch = 0.37, m.yaw = 21.84, m.accNorth = 0.065,
                 m.accEast = 0.064, m.accDown = -0.201;
             })},
            {"4.11 BRS not valid",
             built<Brs>([](Brs &m) { m.time = at(9, 12, 44.6, 2), m.mode = 'N'; })},
            {"4.12 BLS before 1.5 (no time)", built<Bls>([](Bls &m) {
                 m.north = 0.437, m.east = 0.374, m.vertical = -0.04, m.length = 0.576,
                 m.course = 40.61, m.pitch = -4.01, m.mode = 'R';
             })},
            {"4.13 VOG at 4 time decimals", built<Vog>([](Vog &m) {
                 m.time = at(14, 3, 27.8125, 4), m.velNorth = 1.437, m.velEast = 5.374,
                 m.velUp = -0.041, m.mode = 'A';
             })},
            {"4.15 IDL REMOVE refused",
             built<Idl>([](Idl &m) { m.kind = IdlKind::Remove, m.status = "ERROR"; })},
            {"4.15 IDL empty list",
             built<Idl>([](Idl &m) { m.kind = IdlKind::Item, m.count = 0; })},
            {"4.18 TMC without a fix", built<Tmc>([](Tmc &m) {
                 m.time = at(14, 55, 5.28, 2), m.quality = 0, m.satsUsed = 0;
             })},
            {"4.21 SDH not valid",
             built<Sdh>([](Sdh &m) { m.time = at(15, 13, 37.4, 0), m.mode = 'N'; })},
            {"4.22 DOP leap second", built<Dop>([](Dop &m) {
                 m.time = at(23, 59, 60.5, 1), m.gdop = 1.06, m.pdop = 0.94, m.hdop = 0.59,
                 m.vdop = 0.73, m.tdop = 0.5, m.ndop = 0.41, m.edop = 0.42, m.mode = 'D';
             })},
    };
    return rows;
}

const std::map<std::string, Build> &refused() {
    static const std::map<std::string, Build> rows = {
            {"PNVGBRS north",
             built<Brs>([](Brs &m) { m.north = std::numeric_limits<double>::quiet_NaN(); })},
            {"PNVGDOP HDOP",
             built<Dop>([](Dop &m) { m.hdop = std::numeric_limits<double>::infinity(); })},
            {"PNVGBSS RTCM age", built<Bss>([](Bss &m) { m.rtcmAge = 1000; })},
            {"PNVGBSS RTCM messages received", built<Bss>([](Bss &m) { m.rtcmTotal = -1; })},
            {"PNVGVOG mode", built<Vog>([](Vog &m) { m.mode = 'X'; })},
            {"PNVGSDP height deviation", built<Sdp>([](Sdp &m) { m.sdHeight = -0.5; })},
            // 1e300 would print 300 digits.
            {"PNVGIMU north acceleration", built<Imu>([](Imu &m) { m.accNorth = 1e300; })},
            {"PNVGBLS pitch", built<Bls>([](Bls &m) { m.pitch = 91; })},
            {"PNVGSDV time", built<Sdv>([](Sdv &m) {
                 m.time = TimeOfDay{-1, 2};
             })},
            {"PNVGTME time of week", built<Tme>([](Tme &m) { m.counter = 1, m.tow = 604800; })},
            {"PNVGTMU event counter", built<Tmu>([](Tmu &m) { m.counter = -3; })},
            {"PNVGTMC quality", built<Tmc>([](Tmc &m) { m.quality = 3; })},
            {"PNVGTMC DGPS station", built<Tmc>([](Tmc &m) { m.dgpsStation = 1024; })},
            {"nmea.position_decimals", [] { return encodeTmc(Tmc{}, 10); }},
            {"PNVGIDL GLONASS ICB", idlItem(1, 1, 3, 1.5)},
            {"PNVGIDL index", idlItem(2, 3, 3, 0)},
            {"PNVGIDL list length", idlItem(33, 1, 3, 0)},
            {"PNVGIDL station ID", idlItem(1, 1, 4096, 0)},
            // A reply status of "12" would read back as a station id.
            {"PNVGIDL reply",
             built<Idl>([](Idl &m) { m.kind = IdlKind::Remove, m.status = "12"; })},
            {"PNVGTST", [] { return encodeTst(Tst{}); }},
            {"PNVGTST ANT", built<Tst>([](Tst &m) {
                 m.tests = {{"ANT", "3"}};
             })},
            {"PNVGTST ID", built<Tst>([](Tst &m) {
                 m.tests = {{"ID", "x1"}};
             })},
            {"PNVGVER device", built<Ver>([](Ver &m) { m.device = "RT,A"; })},
    };
    return rows;
}

// A _data column "row" with one row per entry of `rows`, named as the entry.
void addRowsNamed(const std::map<std::string, Build> &rows) {
    QTest::addColumn<QString>("row");
    for (const auto &[name, build] : rows)
        QTest::newRow(name.c_str()) << QString::fromStdString(name);
}

} // namespace

class TstNvsOutputEncoders : public QObject {
    Q_OBJECT
private slots:
    // The examples as chapter 4 prints them (checksums valid, docs/spec-notes.md).
    void specExamplesAreRebuiltByteForByte_data() {
        QTest::addColumn<QString>("line");
        QTest::newRow("4.1 VER request") << "$PNVGVER*4E";
        QTest::newRow("4.10 IMU") << "$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7C";
        QTest::newRow("4.11 BRS")
                << "$PNVGBRS,091244.60,4604.566,-1242.064,-27.096,4769.223,344.90,-0.33,R*1A";
        QTest::newRow("4.12 BLS") << "$PNVGBLS,145505.20,0.437,0.374,-0.040,0.576,40.61,-4.01,R*1A";
        QTest::newRow("4.13 VOG") << "$PNVGVOG,140327.80,1.437,5.374,-0.041,R*08";
        QTest::newRow("4.15 IDL MODE") << "$PNVGIDL,MODE,1*7C";
        QTest::newRow("4.15 IDL ADD reply") << "$PNVGIDL,ADD,0003,0.0720*3B";
        QTest::newRow("4.15 IDL REMOVE reply") << "$PNVGIDL,REMOVE,OK*4C";
        QTest::newRow("4.15 IDL CLEAR reply") << "$PNVGIDL,CLEAR,OK*13";
        QTest::newRow("4.15 IDL SHOW item 1") << "$PNVGIDL,4,1,0001,0.0000*54";
        QTest::newRow("4.15 IDL SHOW item 2") << "$PNVGIDL,4,2,0002,0.0020*56";
        QTest::newRow("4.15 IDL SHOW item 3") << "$PNVGIDL,4,3,0032,0.0000*56";
        QTest::newRow("4.15 IDL SHOW item 4") << "$PNVGIDL,4,4,0043,0.0720*52";
        QTest::newRow("4.16 TME") << "$PNVGTME,128,40327.564756284*49";
        QTest::newRow("4.17 TMU") << "$PNVGTMU,128,081248.547824228*61";
        QTest::newRow("4.18 TMC") << "$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,"
                                     "403.995,M,47.848,M,2.2,0002*4D";
        QTest::newRow("4.19 SDP") << "$PNVGSDP,151337.40,0.005,0.004,0.009,R*38";
        QTest::newRow("4.20 SDV") << "$PNVGSDV,151337.40,0.087,0.077,0.118,R*31";
        QTest::newRow("4.21 SDH") << "$PNVGSDH,151337.40,0.978,R*2E";
        QTest::newRow("4.22 DOP") << "$PNVGDOP,121707.80,1.06,0.94,0.59,0.73,0.50,0.41,0.42,R*14";
    }
    void specExamplesAreRebuiltByteForByte() {
        QFETCH(QString, line);
        rebuildsByteForByte(line.toStdString());
    }

    // The same from examples.tsv (every example of the three specs), for the sentences that
    // have an output encoder.
    void examplesTableRowsAreRebuiltByteForByte_data() {
        QTest::addColumn<QString>("line");
        const auto examples = test::loadSpecExamples();
        if (examples.empty()) QSKIP("../shared/specs/examples.tsv not available");
        int rows = 0;
        for (const auto &ex : examples) {
            if (ex.vendor != "nvs") continue;
            Sentence s;
            if (!s.parse(ex.sentence()) || !hasOutputEncoder(s.address())) continue;
            QTest::newRow(ex.sentence().c_str()) << QString::fromStdString(ex.sentence());
            ++rows;
        }
        if (rows == 0) QSKIP("examples.tsv has no row of an NVS output sentence");
    }
    void examplesTableRowsAreRebuiltByteForByte() {
        QFETCH(QString, line);
        rebuildsByteForByte(line.toStdString());
    }

    // No example in the spec (4.1's reply, 4.6 and 4.7 were images; the rest are forms the
    // examples do not show): the message survives the round trip through its sentence.
    void messagesWithoutASpecExampleSurviveTheirSentence_data() { addRowsNamed(withoutExample()); }
    void messagesWithoutASpecExampleSurviveTheirSentence() {
        QFETCH(QString, row);
        const EncodeResult r = withoutExample().at(row.toStdString())();
        QVERIFY2(r.ok(), r.error.c_str());
        QCOMPARE(r.sentences.size(), std::size_t(1));
        const std::string line = r.sentences.front();
        // Decoded, it is the message encoded; encoded again, the same bytes.
        decodeWith("nvs", line, [&](const Message &m) {
            const EncodeResult again = encodeMessage(m);
            QVERIFY2(again.ok(), again.error.c_str());
            QCOMPARE(QString::fromStdString(again.sentences.front()), QString::fromStdString(line));
            decodeWith("nvs", again.sentences.front(),
                       [&](const Message &m2) { QCOMPARE(json(m2), json(m)); });
        });
    }
    void messagesWithoutASpecExampleAreLaidOutAsTheReceiverDoes() {
        const auto body = [](const char *row) {
            const auto r = withoutExample().at(row)();
            return QString::fromStdString(r.sentences.at(0)).section('*', 0, 0);
        };
        QCOMPARE(body("4.1 VER reply"), QString("$PNVGVER,NVS,RTA,0029,CSM24,0101"));
        QCOMPARE(body("4.6 BSS"), QString("$PNVGBSS,128,1,127,4769.223,0.6"));
        QCOMPARE(body("4.6 BSS before any RTCM"), QString("$PNVGBSS,0,0,0,,"));
        QCOMPARE(body("4.7 TST"), QString("$PNVGTST,ID,1254367,ANT,0"));
        QCOMPARE(body("4.11 BRS not valid"), QString("$PNVGBRS,091244.60,,,,,,,N"));
        QCOMPARE(body("4.12 BLS before 1.5 (no time)"),
                 QString("$PNVGBLS,0.437,0.374,-0.040,0.576,40.61,-4.01,R"));
        QCOMPARE(body("4.13 VOG at 4 time decimals"),
                 QString("$PNVGVOG,140327.8125,1.437,5.374,-0.041,A"));
        QCOMPARE(body("4.15 IDL empty list"), QString("$PNVGIDL,0"));
        QCOMPARE(body("4.18 TMC without a fix"), QString("$PNVGTMC,145505.28,,,,,0,00,,,,,,,"));
        QCOMPARE(body("4.21 SDH not valid"), QString("$PNVGSDH,151337,,N"));
        QCOMPARE(body("4.22 DOP leap second"),
                 QString("$PNVGDOP,235960.5,1.06,0.94,0.59,0.73,0.50,0.41,0.42,D"));
    }

    // The row's name is the field the refusal must name.
    void valuesNoReceiverPrintsAreRefused_data() { addRowsNamed(refused()); }
    void valuesNoReceiverPrintsAreRefused() {
        QFETCH(QString, row);
        const EncodeResult r = refused().at(row.toStdString())();
        QVERIFY(!r.ok());
        QVERIFY(r.sentences.empty());
        QVERIFY2(QString::fromStdString(r.error).startsWith(row + ":"), r.error.c_str());
        // In the user's language in the GUI: a template marked for translation.
        QVERIFY(r.refusal.form != nullptr);
        QCOMPARE(r.refusal.text, r.error);
    }
};

QTEST_APPLESS_MAIN(TstNvsOutputEncoders)
#include "tst_nvs_output_encoders.moc"
