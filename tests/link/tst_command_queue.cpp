// CommandQueue against a fake link: every outcome (accepted, refused with the receiver's words,
// timed out after retries, cancelled, link lost), one command at a time, baud changes end to end.
#include "command_queue.h"
#include "core/sentence_builder.h"
#include "dialects.h"
#include "fake_transport.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::FakeTransport;

namespace gnss::link {
// QCOMPARE prints outcomes by name.
char *toString(CommandOutcome o) {
    return qstrdup(qPrintable(outcomeName(o)));
}
} // namespace gnss::link

namespace {

QByteArray line(const char *body) {
    return QByteArray::fromStdString(buildSentence(body)) + "\r\n";
}

const Dialect &dialectById(const char *id) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    return *registry.find(id);
}

// Waits until the queue has finished `n` commands in all.
bool waitForHistory(CommandQueue &q, int n, int ms = 5000) {
    return QTest::qWaitFor([&] { return q.history().size() >= n; }, ms);
}

} // namespace

class TstCommandQueue : public QObject {
    Q_OBJECT
private slots:
    void versionQueryAnsweredIsAccepted() {
        FakeTransport link;
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGVER"))
                t.feed("$GPGGA,partial" + line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        QSignalSpy finished(&q, &CommandQueue::commandFinished);
        const int id = q.enqueue("PNVGVER");
        QVERIFY(id > 0);
        QVERIFY(waitForHistory(q, 1));
        const CommandResult r = q.history().first();
        QCOMPARE(r.id, id);
        QCOMPARE(r.sentence, QStringLiteral("$PNVGVER*4E")); // checksum added
        QCOMPARE(r.outcome, CommandOutcome::Accepted);
        QCOMPARE(r.attempts, 1);
        QCOMPARE(r.replies.size(), 1);
        QVERIFY(r.replies.first().startsWith("$PNVGVER,NVS,RTK"));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(link.written.first(), QByteArray("$PNVGVER*4E\r\n"));
    }

    void refusalCarriesTheReceiversWords() {
        FakeTransport link;
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRTK")) t.feed(line("PNVGRTK,PVTRATE,5")); // asked for 10
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        q.enqueue("$PNVGRTK,PVTRATE,10");
        QVERIFY(waitForHistory(q, 1));
        const CommandResult r = q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Refused);
        QVERIFY2(r.detail.contains("PNVGRTK,PVTRATE,5"), qPrintable(r.detail));
    }

    void silenceTimesOutAfterEveryRetry() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        QSignalSpy sent(&q, &CommandQueue::commandSent);
        CommandOptions o;
        o.timeoutMs = 40;
        o.retries = 2;
        q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::TimedOut);
        QCOMPARE(q.history().first().attempts, 3);
        QCOMPARE(sent.count(), 3);
        QCOMPARE(link.written.size(), 3);
    }

    void answerToARetryIsAccepted() {
        FakeTransport link;
        link.open();
        int seen = 0;
        link.responder = [&](FakeTransport &t, const QByteArray &) {
            if (++seen == 2) t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        CommandOptions o;
        o.timeoutMs = 40;
        q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::Accepted);
        QCOMPARE(q.history().first().attempts, 2);
    }

    void commandsGoOneAtATimeInOrder() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        q.enqueue("PNVGVER");
        q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(link.written.size(), 1);
        QTest::qWait(50);
        QCOMPARE(link.written.size(), 1); // the second waits for the first's answer
        link.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        QTRY_COMPARE(link.written.size(), 2);
        QVERIFY(link.written[1].startsWith("$GPGPQ,PNVGTST*"));
        link.feed(line("PNVGTST,1,1,1"));
        QVERIFY(waitForHistory(q, 2));
        QCOMPARE(q.history()[1].outcome, CommandOutcome::Accepted);
    }

    void badChecksumReplyIsNotTaken() {
        FakeTransport link;
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed("$PNVGVER,NVS,RTK,0207,CSM24,0405*00\r\n");
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        CommandOptions o;
        o.timeoutMs = 40;
        o.retries = 0;
        q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::TimedOut);
    }

    void commandWithoutReplyCountsAsSent() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        q.enqueue("PNVGRST,W");
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::Sent);
    }

    void unknownDialectFindsTheRuleAmongOthers() {
        FakeTransport link;
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed(line("GPSGG,RQUERY,GEOS-5,V.5.102,150324,0000,0000,0000"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setOtherDialects({&dialectById("nvs"), &dialectById("geostar")});
        q.enqueue("$GPSGG,RQUERY");
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::Accepted);
    }

    void standardQueryIsAnsweredByTheSentenceAsked() {
        FakeTransport link;
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed(line("GPRMC,100000.00,A,5540.0000,N,03730.0000,E,0.0,0.0,150324,,,A"));
            t.feed(line("GPGLL,5540.0000,N,03730.0000,E,100000.00,A,A"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.enqueue("GPGPQ,GLL");
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::Accepted);
        QVERIFY(q.history().first().replies.first().startsWith("$GPGLL"));
    }

    void malformedSentenceIsRefusedBeforeSending() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        QString error;
        QCOMPARE(q.enqueue("PNVG\x01VER", {}, &error), -1);
        QVERIFY(error.contains("not allowed"));
        QCOMPARE(q.enqueue("   ", {}, &error), -1);
        QVERIFY(!error.isEmpty());
        QTest::qWait(20);
        QVERIFY(link.written.isEmpty());
    }

    void cancelStopsTheRunningAndTheQueuedCommand() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        const int a = q.enqueue("PNVGVER");
        const int b = q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(link.written.size(), 1);
        QVERIFY(q.cancel(b));
        QVERIFY(q.cancel(a));
        QVERIFY(!q.cancel(a));
        QCOMPARE(q.history().size(), 2);
        for (const auto &r : q.history()) QCOMPARE(r.outcome, CommandOutcome::Cancelled);
        link.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405")); // too late: ignored
        QTest::qWait(30);
        QCOMPARE(q.history().size(), 2);
        QCOMPARE(link.written.size(), 1);
    }

    void lostLinkFailsTheRunningAndEveryQueuedCommand() {
        FakeTransport link;
        link.open();
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        q.enqueue("PNVGVER");
        q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(link.written.size(), 1);
        link.drop(QStringLiteral("unplugged"));
        QVERIFY(waitForHistory(q, 2));
        QCOMPARE(q.history()[0].outcome, CommandOutcome::LinkLost);
        QVERIFY(q.history()[0].detail.contains("unplugged"));
        QCOMPARE(q.history()[1].outcome, CommandOutcome::LinkLost);
        QCOMPARE(link.written.size(), 1);
        // And a command for a closed link is not sent at all.
        q.enqueue("PNVGVER");
        QVERIFY(waitForHistory(q, 3));
        QCOMPARE(q.history()[2].outcome, CommandOutcome::LinkLost);
    }

    void baudChangeSwitchesThePortAndConfirmsTraffic() {
        FakeTransport link(115200);
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
            // At the new speed the receiver answers its probe.
            if (w.startsWith("$PNVGVER") && t.baud() == 38400)
                t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        QSignalSpy bauds(&q, &CommandQueue::baudChanged);
        q.enqueue("PNVGRZA,1,38400,1");
        QVERIFY(waitForHistory(q, 1));
        const CommandResult r = q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Accepted);
        QCOMPARE(r.baudBefore, 115200);
        QCOMPARE(r.baudAfter, 38400);
        QCOMPARE(link.baud(), 38400);
        QCOMPARE(bauds.count(), 1);
    }

    void baudChangeWithoutTrafficFallsBackAndSaysSo() {
        FakeTransport link(115200);
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
            // The receiver did not really switch: it still answers at the old speed.
            if (w.startsWith("$PNVGVER") && t.baud() == 115200)
                t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        CommandOptions o;
        o.confirmMs = 100;
        q.enqueue("PNVGRZA,1,38400,1", o);
        QVERIFY(waitForHistory(q, 1));
        const CommandResult r = q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Failed);
        QCOMPARE(link.baud(), 115200);
        QCOMPARE(link.bauds, (QList<int>{38400, 115200}));
        QVERIFY2(r.detail.contains("38400") && r.detail.contains("115200"), qPrintable(r.detail));
    }

    void baudChangeLostAtBothRatesIsALostLink() {
        FakeTransport link(115200);
        link.open();
        link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
        };
        SentenceStream stream(&link, test::builtinRegistry());
        CommandQueue q(&link, &stream);
        q.setDialect(&dialectById("nvs"));
        CommandOptions o;
        o.confirmMs = 60;
        q.enqueue("PNVGRZA,1,38400,1", o);
        QVERIFY(waitForHistory(q, 1));
        QCOMPARE(q.history().first().outcome, CommandOutcome::LinkLost);
        QCOMPARE(link.baud(), 115200);
    }
};

QTEST_GUILESS_MAIN(TstCommandQueue)
#include "tst_command_queue.moc"
