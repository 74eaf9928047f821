// The GeoS-5's own output built by its encoders (geostar_encoders.h): each of the spec's example
// replies decoded with the geostar dialect and encoded again gives the example byte for byte
// (RQUERY 3.11, NQUERY 3.12, JAMDET 3.13, RLM 3.10, the subsidiary GNS sentences of 3.3), the
// same for every such row of examples.tsv, and a value a sentence cannot carry is refused with
// nothing built.
#include "examples_table.h"
#include "vendor_refusal_rows.h"

#include "builtin/dialects.h"
#include "core/stream_decoder.h"
#include "geostar/geostar_encoders.h"
#include "nmea/nmea_encoders.h"

#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <functional>

using namespace gnss;
using namespace gnss::geostar;
using gnss::test::encodedAfter;

namespace {

// The encoder of the message's kind (the subsidiary GNS takes its talker from the address).
EncodeResult encodeMessage(const Sentence &s, const Message &m) {
    if (const auto *q = message_cast<Rquery>(m)) return encodeRquery(*q);
    if (const auto *n = message_cast<Nquery>(m)) return encodeNquery(*n);
    if (const auto *j = message_cast<Jamdet>(m)) return encodeJamdet(*j);
    if (const auto *r = message_cast<Rlm>(m)) return encodeRlm(*r);
    if (const auto *g = message_cast<nmea::Gns>(m))
        return encodeSubsidiaryGns(s.address().substr(0, 2), *g);
    EncodeResult none;
    none.error = "no encoder for this message";
    return none;
}

// Decodes `line` (checksum checked) and hands the message to `use` while it is valid.
QString decoded(const std::string &line,
                const std::function<void(const Sentence &, const Message &)> &use) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    DecoderOptions o;
    o.dialect = "geostar";
    StreamDecoder d(registry, o);
    QString error = "nothing decoded";
    d.decodeLine(line, [&](const SentenceEvent &ev) {
        if (!ev.message) {
            error = QString::fromStdString(std::string(ev.error));
            return;
        }
        error.clear();
        use(ev.sentence, *ev.message);
    });
    return error;
}

// encode(decode(line)), or why not.
// The one sentence `e` built, without its checksum; or why it built none.
QString builtBody(const EncodeResult &e) {
    if (!e.ok()) return "refused: " + QString::fromStdString(e.error);
    return QString::fromStdString(e.sentences.front()).section('*', 0, 0);
}

QString reencoded(const std::string &line) {
    QString out;
    const QString error = decoded(line, [&](const Sentence &s, const Message &m) {
        const EncodeResult r = encodeMessage(s, m);
        if (!r.ok())
            out = "refused: " + QString::fromStdString(r.error);
        else if (r.sentences.size() != 1)
            out = "not one sentence";
        else
            out = QString::fromStdString(r.sentences.front());
    });
    return error.isEmpty() ? out : "not decoded: " + error;
}

// A subsidiary GNS sentence: time, four empty fields, the system's satellite count.
const QRegularExpression kSubsidiaryGns(R"(^\$G[PLAQ]GNS,[0-9.]*,,,,,\d+,)");

bool isGeoStarReply(const QString &s) {
    return (s.startsWith("$GPSGG,RQUERY,") || s.startsWith("$GPSGG,NQUERY,") ||
            s.startsWith("$GPSGG,JAMDET") || s.startsWith("$GPRLM,") ||
            kSubsidiaryGns.match(s).hasMatch());
}

Rquery validRquery() {
    Rquery q;
    q.receiverName = "GEOS-5";
    q.firmware = "V.5.102";
    q.firmwareDate = Date{2018, 5, 10};
    return q;
}

Nquery validNquery() {
    Nquery n;
    n.port = 1;
    n.rateCode = 3;
    n.nmeaVersion = 2;
    n.codes.fill('0');
    n.codeCount = Nquery::kMessages;
    return n;
}

Rlm validRlm() {
    Rlm r;
    r.beaconId = "123456789ABCD12";
    r.time = nmea::timeOfDay(128, 2);
    r.messageCode = 3;
    r.parameters = "0000";
    return r;
}

nmea::Gns validGns() {
    nmea::Gns g;
    g.time = nmea::timeOfDay(8 * 3600 + 6 * 60 + 6, 2);
    g.satsUsed = 9;
    return g;
}

struct Refused {
    const char *name;
    std::function<EncodeResult()> encode;
    const char *field; // what the refusal names
};

// A refusal row's encoder: the valid subsidiary GNS as `change` leaves it, sent with `talker`.
std::function<EncodeResult()> gnsAfter(const char *talker, void (*change)(nmea::Gns &)) {
    return encodedAfter(
            validGns(), [talker](const nmea::Gns &g) { return encodeSubsidiaryGns(talker, g); },
            change);
}

const std::vector<Refused> &refusedInputs() {
    static const std::vector<Refused> rows = {
            {"RQUERY name with a comma",
             encodedAfter(validRquery(), encodeRquery,
                          [](Rquery &q) { q.receiverName = "GEOS,5"; }),
             "receiver name"},
            {"RQUERY firmware too long",
             encodedAfter(validRquery(), encodeRquery,
                          [](Rquery &q) { q.firmware = "V.5.102-0123456789"; }),
             "firmware"},
            {"RQUERY month 13",
             encodedAfter(validRquery(), encodeRquery,
                          [](Rquery &q) {
                              q.firmwareDate = Date{2018, 13, 10};
                          }),
             "firmware date"},
            {"RQUERY antenna state 4",
             encodedAfter(validRquery(), encodeRquery,
                          [](Rquery &q) { q.status.antenna = static_cast<AntennaState>(4); }),
             "antenna"},
            {"RQUERY rate code 7",
             encodedAfter(validRquery(), encodeRquery, [](Rquery &q) { q.config1.rateCode = 7; }),
             "rate code"},
            {"RQUERY datum code 4",
             encodedAfter(validRquery(), encodeRquery, [](Rquery &q) { q.config2.datumCode = 4; }),
             "datum"},
            {"NQUERY port 2",
             encodedAfter(validNquery(), encodeNquery, [](Nquery &n) { n.port = 2; }), "port"},
            {"NQUERY rate code 4",
             encodedAfter(validNquery(), encodeNquery, [](Nquery &n) { n.rateCode = 4; }),
             "rate code"},
            {"NQUERY NMEA version 3",
             encodedAfter(validNquery(), encodeNquery, [](Nquery &n) { n.nmeaVersion = 3; }),
             "NMEA version"},
            {"NQUERY message code X",
             encodedAfter(validNquery(), encodeNquery, [](Nquery &n) { n.codes[2] = 'X'; }),
             "message rate code"},
            {"NQUERY 11 message codes",
             encodedAfter(validNquery(), encodeNquery, [](Nquery &n) { n.codeCount = 11; }),
             "message rate codes"},
            {"RLM beacon of 14 digits",
             encodedAfter(validRlm(), encodeRlm, [](Rlm &r) { r.beaconId = "123456789ABCD1"; }),
             "beacon id"},
            {"RLM beacon not hex",
             encodedAfter(validRlm(), encodeRlm, [](Rlm &r) { r.beaconId = "123456789ABCDG2"; }),
             "beacon id"},
            {"RLM message code 16",
             encodedAfter(validRlm(), encodeRlm, [](Rlm &r) { r.messageCode = 16; }),
             "message code"},
            {"RLM without a message code",
             encodedAfter(validRlm(), encodeRlm, [](Rlm &r) { r.messageCode.reset(); }),
             "message code"},
            {"RLM parameters of 5 digits",
             encodedAfter(validRlm(), encodeRlm, [](Rlm &r) { r.parameters = "00000"; }),
             "parameters"},
            {"RLM time past the day",
             encodedAfter(validRlm(), encodeRlm,
                          [](Rlm &r) { r.time->nanos = 86'400'000'000'000LL; }),
             "time"},
            {"GNS talker GN", [] { return encodeSubsidiaryGns("GN", validGns()); }, "talker"},
            {"GNS without satellites", gnsAfter("GP", [](nmea::Gns &g) { g.satsUsed.reset(); }),
             "satellites used"},
            {"GNS 100 satellites", gnsAfter("GP", [](nmea::Gns &g) { g.satsUsed = 100; }),
             "satellites used"},
            {"GNS age 1000 s", gnsAfter("GL", [](nmea::Gns &g) { g.dgpsAge = 1000; }), "DGPS age"},
            {"GNS age not a number", gnsAfter("GL", [](nmea::Gns &g) { g.dgpsAge = std::nan(""); }),
             "DGPS age"},
            {"GNS station 4096", gnsAfter("GA", [](nmea::Gns &g) { g.dgpsStation = 4096; }),
             "DGPS station"},
            {"GNS navigational status 1", gnsAfter("GQ", [](nmea::Gns &g) { g.navStatus = '1'; }),
             "navigational status"},
    };
    return rows;
}

} // namespace

class TstGeostarReplyEncoders : public QObject {
    Q_OBJECT
private slots:
    // The spec's examples, typed from its text; the address as the checksums prove it
    // (docs/spec-notes.md: the spec prints RQUERY as $GPGSGG and NQUERY as $GPGG).
    void specExampleIsEncodedAgainByteForByte_data() {
        QTest::addColumn<QString>("line");
        for (const char *line : {
                     "$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C", // 3.11
                     "$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71",                        // 3.12
                     "$GPSGG,JAMDET,*57",                                                 // 3.13
                     "$GPRLM,123456789ABCD12,000128.00,3,333344445555666677778888*64",    // 3.10
                     // 3.3, autonomous GPS+GLONASS+Galileo, then differential GPS and GLONASS:
                     "$GPGNS,080520.00,,,,,11,,,,,*40",
                     "$GLGNS,080520.00,,,,,09,,,,,*55",
                     "$GAGNS,080520.00,,,,,05,,,,,*54",
                     "$GPGNS,080606.00,,,,,11,,,,,001.0,0000,*68",
                     "$GLGNS,080606.00,,,,,09,,,,,001.0,0000,*7D",
                     "$GAGNS,080606.00,,,,,05,,,,,*53",
             })
            QTest::newRow(line) << QString(line);
    }
    void specExampleIsEncodedAgainByteForByte() {
        QFETCH(QString, line);
        QCOMPARE(reencoded(line.toStdString()), line);
    }

    // Every row of examples.tsv for these sentences whose checksum the table proves (ok, or a
    // typo with its corrected text).
    void examplesTableRowsAreEncodedAgain_data() {
        QTest::addColumn<QString>("line");
        const auto examples = gnss::test::loadSpecExamples();
        if (examples.empty()) QSKIP("../shared/specs/examples.tsv not available");
        int n = 0;
        for (const auto &e : examples) {
            const QString s = QString::fromStdString(e.sentence());
            if (e.vendor != "geostar" || e.verdict == "bad" || !isGeoStarReply(s)) continue;
            QTest::addRow("%d %s", ++n, qPrintable(s)) << s;
        }
        // RQUERY, NQUERY, RLM, six subsidiary GNS sentences and JAMDET twice (the revision
        // history, and 3.13 with its misprinted address).
        QCOMPARE(n, 11);
    }
    void examplesTableRowsAreEncodedAgain() {
        QFETCH(QString, line);
        QCOMPARE(reencoded(line.toStdString()), line);
    }

    // The GeoS-5 RTK's subsidiary sentences carry no navigational status field at all; the spec
    // prints them one comma short besides (restoring the comma gives the printed checksum; see
    // geostar_gns.cpp). The encoder writes the GeoS-5M's form (an empty status field after the
    // station), so this one comes back field for field, not byte for byte.
    void rtkSubsidiaryGnsComesBackFieldForField_data() {
        QTest::addColumn<QString>("line");
        QTest::newRow("GPS") << "$GPGNS,153632.00,,,,,09,,,,,000.8,0100*4D";
        QTest::newRow("GLONASS") << "$GLGNS,153632.00,,,,,06,,,,,000.6,0100*50";
    }
    void rtkSubsidiaryGnsComesBackFieldForField() {
        QFETCH(QString, line);
        std::optional<nmea::Gns> first;
        std::string encoded;
        QCOMPARE(decoded(line.toStdString(),
                         [&](const Sentence &s, const Message &m) {
                             const auto *g = message_cast<nmea::Gns>(m);
                             if (!g) return;
                             first = *g;
                             const EncodeResult r =
                                     encodeSubsidiaryGns(s.address().substr(0, 2), *g);
                             if (r.ok()) encoded = r.sentences.front();
                         }),
                 QString());
        QVERIFY(first && !encoded.empty());
        // The same fields and one more, empty.
        QCOMPARE(QString::fromStdString(encoded).section('*', 0, 0), line.section('*', 0, 0) + ",");
        QCOMPARE(decoded(encoded,
                         [&](const Sentence &, const Message &m) {
                             const auto *g = message_cast<nmea::Gns>(m);
                             QVERIFY(g);
                             QCOMPARE(g->time, first->time);
                             QCOMPARE(g->satsUsed, first->satsUsed);
                             QCOMPARE(g->dgpsAge, first->dgpsAge);
                             QCOMPARE(g->dgpsStation, first->dgpsStation);
                             QCOMPARE(g->navStatus, first->navStatus);
                             QVERIFY(g->mode.empty() && !g->lat && !g->hdop);
                         }),
                 QString());
    }

    // What a receiver fills in comes back from the decoder as it was given.
    void aReplyFilledInFieldByFieldDecodesToItself() {
        Nquery n = validNquery();
        const char codes[] = "R1230RRR1R";
        for (std::size_t i = 0; i < Nquery::kMessages; ++i) n.codes[i] = codes[i];
        n.nmeaVersion = 4;
        n.port = 0;
        const EncodeResult e = encodeNquery(n);
        QCOMPARE(builtBody(e), QString("$GPSGG,NQUERY,0,3,4,R,1,2,3,0,R,R,R,1,R"));
        QCOMPARE(reencoded(e.sentences.front()), QString::fromStdString(e.sentences.front()));

        Rquery q = validRquery();
        q.firmwareDate.reset(); // an empty field
        q.status.active = true;
        q.config1.rateCode = rateHzToCode(5);
        q.config2.receiverTypeCode = 0xF7FD;
        const EncodeResult r = encodeRquery(q);
        QCOMPARE(builtBody(r), QString("$GPSGG,RQUERY,GEOS-5,V.5.102,,00800000,00040000,F7FD0000"));
        QCOMPARE(reencoded(r.sentences.front()), QString::fromStdString(r.sentences.front()));

        Rlm l = validRlm();
        l.messageCode = 0xF;
        const EncodeResult t = encodeRlm(l);
        QCOMPARE(builtBody(t), QString("$GPRLM,123456789ABCD12,000208.00,F,0000"));
    }

    void aValueTheSentenceCannotCarryIsRefused_data() {
        QTest::addColumn<int>("row");
        for (std::size_t i = 0; i < refusedInputs().size(); ++i)
            QTest::newRow(refusedInputs()[i].name) << int(i);
    }
    void aValueTheSentenceCannotCarryIsRefused() {
        QFETCH(int, row);
        const Refused &r = refusedInputs()[std::size_t(row)];
        const EncodeResult e = r.encode();
        QVERIFY(!e.ok());
        QVERIFY(e.sentences.empty()); // nothing built
        QVERIFY2(QString::fromStdString(e.error).contains(r.field), e.error.c_str());
        QVERIFY(e.refusal.form); // a translatable template, shown in the user's language
    }
};

QTEST_APPLESS_MAIN(TstGeostarReplyEncoders)
#include "tst_geostar_reply_encoders.moc"
