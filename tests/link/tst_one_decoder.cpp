// One decoder per link: however many listeners a connection has (command queue, baud and vendor
// detection, the views' session, a recorder, the command line), each sentence received is framed
// and decoded exactly once, and the byte and sentence counts come from that one place. Counted
// with a test dialect whose decoder counts its calls.
#include "builtin/dialects.h"
#include "config/settings_engine.h"
#include "core/sentence_builder.h"
#include "fake_transport.h"
#include "link/baud_detector.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "link/vendor_detector.h"
#include "models/model_feed.h"
#include "nmea/nmea_rules.h"

#include <QTest>

#include <random>

using namespace gnss;
using namespace gnss::link;

namespace {

int g_decodeCalls = 0; // calls of the counting dialect's decoder

struct Counted : Message {
    static const MessageType kType;
    Counted() : Message(kType) {}
    void writeJson(JsonWriter &w) const override { w.beginObject().endObject(); }
};
const MessageType Counted::kType{"PTSTC"};

bool decodeCounted(const Sentence &, DecodeContext &ctx) {
    ++g_decodeCalls;
    Counted c;
    ctx.deliver(c);
    return true;
}

constexpr SentenceRule kRules[] = {{"PTSTC", AddressMatch::Whole, decodeCounted, "counted"}};
const Dialect kCounting{.id = "counting", .displayName = "Counting", .rules = kRules};

} // namespace

class TstOneDecoder : public QObject {
    Q_OBJECT
private slots:
    void eachSentenceIsDecodedOnceWhateverListens() {
        const DialectRegistry registry(standardSentenceRules(), {&kCounting, &nmeaDialect()});
        auto owned = std::make_unique<link::test::FakeTransport>(115200);
        link::test::FakeTransport *fake = owned.get();
        Connection conn(std::move(owned), registry, {.dialect = "counting"});
        QVERIFY(conn.open());
        // The listeners the application puts on a link (the connection's own command queue and
        // recorder among them), and two more of the kind a view adds.
        BaudDetector baud(conn.stream());
        VendorDetector vendor(conn.stream());
        // The settings engine on the connection, and the views' session fed as the application's
        // receiver session feeds it (its counts from the link's decoder).
        config::SettingsEngine engine;
        engine.attach(&conn, registry.find("counting"));
        ui::ReceiverStateModel stateModel;
        ui::SatelliteModel satellites;
        ui::MessageStatsModel messages;
        ui::ConsoleModel console;
        ui::ModelFeed session(registry, {&stateModel, &satellites, &messages, &console});
        session.setCounterSource(&conn.decoder());
        int consumed = 0;
        connect(conn.stream(), &SentenceStream::sentenceDecoded, &session,
                [&](const SentenceEvent &ev) {
                    session.consume(ev, conn.stream()->dialect());
                    ++consumed;
                });
        int heard[2] = {0, 0};
        for (int &n : heard)
            connect(conn.stream(), &SentenceStream::sentenceDecoded, this,
                    [&n](const SentenceEvent &ev) {
                        if (ev.message) ++n;
                    });

        // 2,000 sentences in chunks of random size, as a serial driver hands them over.
        QByteArray all;
        constexpr int kSentences = 2000;
        for (int i = 0; i < kSentences; ++i)
            all += QByteArray::fromStdString(
                    buildSentence("PTSTC," + std::to_string(i) + ",payload") + "\r\n");
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> chunk(1, 300);
        g_decodeCalls = 0;
        for (qsizetype at = 0; at < all.size();) {
            const qsizetype n = std::min<qsizetype>(chunk(rng), all.size() - at);
            fake->feed(all.mid(at, n));
            at += n;
        }

        QCOMPARE(g_decodeCalls, kSentences); // one decode per sentence received
        QCOMPARE(heard[0], kSentences);      // and every listener heard each one
        QCOMPARE(heard[1], kSentences);
        // The counts are the one decoder's, and match what was received.
        QCOMPARE(conn.bytesReceived(), quint64(all.size()));
        QCOMPARE(conn.decoder().framerStats().bytesIn, std::uint64_t(all.size()));
        QCOMPARE(conn.decoder().framerStats().sentences, std::uint64_t(kSentences));
        QCOMPARE(consumed, kSentences);
        session.refresh();
        QCOMPARE(session.counters().bytes, quint64(all.size()));
        QCOMPARE(session.counters().sentences, quint64(kSentences));
    }
};

QTEST_GUILESS_MAIN(TstOneDecoder)
#include "tst_one_decoder.moc"
