// CommandQueue against a fake link: every outcome (accepted, refused with the receiver's words,
// timed out after retries, cancelled, link lost), one command at a time, baud changes end to end.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "fake_transport.h"
#include "link/command_queue.h"
#include "queue_checks.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::FakeTransport;

namespace {

QByteArray line(const char *body) {
    return QByteArray::fromStdString(buildSentence(body)) + "\r\n";
}

const Dialect &dialectById(const char *id) {
    return *gnss::test::builtinRegistry().find(id);
}

// A command queue on an open fake link (at `baud`) that it reads through its own stream, speaking
// `dialect` (nullptr: none yet).
struct OpenFakeLink {
    FakeTransport link;
    explicit OpenFakeLink(int baud) : link(baud) { link.open(); }
};
struct QueueRig : OpenFakeLink {
    SentenceStream stream;
    CommandQueue q;
    explicit QueueRig(const char *dialect = "nvs", int baud = 0)
        : OpenFakeLink(baud), stream(&link, gnss::test::builtinRegistry()), q(&link, &stream) {
        if (dialect) q.setDialect(&dialectById(dialect));
    }
};

} // namespace

class TstCommandQueue : public QObject {
    Q_OBJECT
private slots:
    void versionQueryAnsweredIsAccepted() {
        QueueRig rig;
        rig.link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGVER"))
                t.feed("$GPGGA,partial" + line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        QSignalSpy finished(&rig.q, &CommandQueue::commandFinished);
        const int id = rig.q.enqueue("PNVGVER");
        QVERIFY(id > 0);
        QVERIFY(waitForHistory(rig.q, 1));
        const CommandResult r = rig.q.history().first();
        QCOMPARE(r.id, id);
        QCOMPARE(r.sentence, QStringLiteral("$PNVGVER*4E")); // checksum added
        QCOMPARE(r.outcome, CommandOutcome::Accepted);
        QCOMPARE(r.attempts, 1);
        QCOMPARE(r.replies.size(), 1);
        QVERIFY(r.replies.first().startsWith("$PNVGVER,NVS,RTK"));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(rig.link.written.first(), QByteArray("$PNVGVER*4E\r\n"));
    }

    void refusalCarriesTheReceiversWords() {
        QueueRig rig;
        rig.link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRTK")) t.feed(line("PNVGRTK,PVTRATE,5")); // asked for 10
        };
        rig.q.enqueue("$PNVGRTK,PVTRATE,10");
        QVERIFY(waitForHistory(rig.q, 1));
        const CommandResult r = rig.q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Refused);
        QVERIFY2(r.detail.contains("PNVGRTK,PVTRATE,5"), qPrintable(r.detail));
    }

    void silenceTimesOutAfterEveryRetry() {
        QueueRig rig;
        QSignalSpy sent(&rig.q, &CommandQueue::commandSent);
        CommandOptions o;
        o.timeoutMs = 40;
        o.retries = 2;
        rig.q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::TimedOut);
        QCOMPARE(rig.q.history().first().attempts, 3);
        QCOMPARE(sent.count(), 3);
        QCOMPARE(rig.link.written.size(), 3);
    }

    void answerToARetryIsAccepted() {
        QueueRig rig;
        int seen = 0;
        rig.link.responder = [&](FakeTransport &t, const QByteArray &) {
            if (++seen == 2) t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        CommandOptions o;
        o.timeoutMs = 40;
        rig.q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::Accepted);
        QCOMPARE(rig.q.history().first().attempts, 2);
    }

    void commandsGoOneAtATimeInOrder() {
        QueueRig rig;
        rig.q.enqueue("PNVGVER");
        rig.q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(rig.link.written.size(), 1);
        QTest::qWait(50);
        QCOMPARE(rig.link.written.size(), 1); // the second waits for the first's answer
        rig.link.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        QTRY_COMPARE(rig.link.written.size(), 2);
        QVERIFY(rig.link.written[1].startsWith("$GPGPQ,PNVGTST*"));
        rig.link.feed(line("PNVGTST,1,1,1"));
        QVERIFY(waitForHistory(rig.q, 2));
        QCOMPARE(rig.q.history()[1].outcome, CommandOutcome::Accepted);
    }

    void badChecksumReplyIsNotTaken() {
        QueueRig rig;
        rig.link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed("$PNVGVER,NVS,RTK,0207,CSM24,0405*00\r\n");
        };
        CommandOptions o;
        o.timeoutMs = 40;
        o.retries = 0;
        rig.q.enqueue("PNVGVER", o);
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::TimedOut);
    }

    void commandWithoutReplyCountsAsSent() {
        QueueRig rig;
        rig.q.enqueue("PNVGRST,W");
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::Sent);
    }

    void unknownDialectFindsTheRuleAmongOthers() {
        QueueRig rig(nullptr);
        rig.link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed(line("GPSGG,RQUERY,GEOS-5,V.5.102,150324,0000,0000,0000"));
        };
        rig.q.setOtherDialects({&dialectById("nvs"), &dialectById("geostar")});
        rig.q.enqueue("$GPSGG,RQUERY");
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::Accepted);
    }

    void standardQueryIsAnsweredByTheSentenceAsked() {
        QueueRig rig(nullptr);
        rig.link.responder = [](FakeTransport &t, const QByteArray &) {
            t.feed(line("GPRMC,100000.00,A,5540.0000,N,03730.0000,E,0.0,0.0,150324,,,A"));
            t.feed(line("GPGLL,5540.0000,N,03730.0000,E,100000.00,A,A"));
        };
        rig.q.enqueue("GPGPQ,GLL");
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::Accepted);
        QVERIFY(rig.q.history().first().replies.first().startsWith("$GPGLL"));
    }

    void malformedSentenceIsRefusedBeforeSending() {
        QueueRig rig(nullptr);
        QString error;
        QCOMPARE(rig.q.enqueue("PNVG\x01VER", {}, &error), -1);
        QVERIFY(error.contains("not allowed"));
        QCOMPARE(rig.q.enqueue("   ", {}, &error), -1);
        QVERIFY(!error.isEmpty());
        QTest::qWait(20);
        QVERIFY(rig.link.written.isEmpty());
    }

    // NMEA 0183's 82 characters and the NVS receiver's 512, line end included.
    void sentenceLongerThanTheReceiverTakesIsRefusedBeforeSending() {
        for (const char *id : {"nmea", "nvs"}) {
            QueueRig rig(id);
            const int max = int(dialectById(id).maxSentenceLength);
            // "$" + typed + "*hh" + "\r\n": six characters more than what is typed.
            QString typed = "PXXXX," + QString(max - 5 - 6, 'A');
            QString error;
            QCOMPARE(rig.q.enqueue(typed, {}, &error), -1);
            QVERIFY2(error.contains(QString::number(max + 1)) &&
                             error.contains(QString::number(max)),
                     qPrintable(QString("%1: %2").arg(id, error)));
            QTest::qWait(20);
            QVERIFY(rig.link.written.isEmpty());
            QVERIFY(rig.q.history().isEmpty());
            // One character less fits exactly, and is sent.
            typed.chop(1);
            QVERIFY2(rig.q.enqueue(typed, {}, &error) > 0, id);
            QTRY_COMPARE(rig.link.written.size(), 1);
            QCOMPARE(rig.link.written.first().size(), qsizetype(max));
        }
    }

    void withoutADialectOnlyTheFramersLimitApplies() {
        QueueRig rig(nullptr);
        QVERIFY(rig.q.enqueue("PXXXX," + QString(200, 'A')) > 0);
        QTRY_COMPARE(rig.link.written.size(), 1);
    }

    void cancelStopsTheRunningAndTheQueuedCommand() {
        QueueRig rig;
        const int a = rig.q.enqueue("PNVGVER");
        const int b = rig.q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(rig.link.written.size(), 1);
        QVERIFY(rig.q.cancel(b));
        QVERIFY(rig.q.cancel(a));
        QVERIFY(!rig.q.cancel(a));
        QCOMPARE(rig.q.history().size(), 2);
        for (const auto &r : rig.q.history()) QCOMPARE(r.outcome, CommandOutcome::Cancelled);
        rig.link.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405")); // too late: ignored
        QTest::qWait(30);
        QCOMPARE(rig.q.history().size(), 2);
        QCOMPARE(rig.link.written.size(), 1);
    }

    void lostLinkFailsTheRunningAndEveryQueuedCommand() {
        QueueRig rig;
        rig.q.enqueue("PNVGVER");
        rig.q.enqueue("GPGPQ,PNVGTST");
        QTRY_COMPARE(rig.link.written.size(), 1);
        rig.link.drop(QStringLiteral("unplugged"));
        QVERIFY(waitForHistory(rig.q, 2));
        QCOMPARE(rig.q.history()[0].outcome, CommandOutcome::LinkLost);
        QVERIFY(rig.q.history()[0].detail.contains("unplugged"));
        QCOMPARE(rig.q.history()[1].outcome, CommandOutcome::LinkLost);
        QCOMPARE(rig.link.written.size(), 1);
        // And a command for a closed link is not sent at all.
        rig.q.enqueue("PNVGVER");
        QVERIFY(waitForHistory(rig.q, 3));
        QCOMPARE(rig.q.history()[2].outcome, CommandOutcome::LinkLost);
    }

    void baudChangeSwitchesThePortAndConfirmsTraffic() {
        QueueRig rig("nvs", 115200);
        rig.link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
            // At the new speed the receiver answers its probe.
            if (w.startsWith("$PNVGVER") && t.baud() == 38400)
                t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        QSignalSpy bauds(&rig.q, &CommandQueue::baudChanged);
        rig.q.enqueue("PNVGRZA,1,38400,1");
        QVERIFY(waitForHistory(rig.q, 1));
        const CommandResult r = rig.q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Accepted);
        QCOMPARE(r.baudBefore, 115200);
        QCOMPARE(r.baudAfter, 38400);
        QCOMPARE(rig.link.baud(), 38400);
        QCOMPARE(bauds.count(), 1);
    }

    void baudChangeWithoutTrafficFallsBackAndSaysSo() {
        QueueRig rig("nvs", 115200);
        rig.link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
            // The receiver did not really switch: it still answers at the old speed.
            if (w.startsWith("$PNVGVER") && t.baud() == 115200)
                t.feed(line("PNVGVER,NVS,RTK,0207,CSM24,0405"));
        };
        CommandOptions o;
        o.confirmMs = 100;
        rig.q.enqueue("PNVGRZA,1,38400,1", o);
        QVERIFY(waitForHistory(rig.q, 1));
        const CommandResult r = rig.q.history().first();
        QCOMPARE(r.outcome, CommandOutcome::Failed);
        QCOMPARE(rig.link.baud(), 115200);
        QCOMPARE(rig.link.bauds, (QList<int>{38400, 115200}));
        QVERIFY2(r.detail.contains("38400") && r.detail.contains("115200"), qPrintable(r.detail));
    }

    void baudChangeLostAtBothRatesIsALostLink() {
        QueueRig rig("nvs", 115200);
        rig.link.responder = [](FakeTransport &t, const QByteArray &w) {
            if (w.startsWith("$PNVGRZA")) t.feed(line("PNVGRZA,1,38400,1"));
        };
        CommandOptions o;
        o.confirmMs = 60;
        rig.q.enqueue("PNVGRZA,1,38400,1", o);
        QVERIFY(waitForHistory(rig.q, 1));
        QCOMPARE(rig.q.history().first().outcome, CommandOutcome::LinkLost);
        QCOMPARE(rig.link.baud(), 115200);
    }

    // A session polling for days keeps the last results, not all of them; every command is still
    // reported as it finishes.
    void historyKeepsTheLastCommands() {
        QueueRig rig;
        QSignalSpy finished(&rig.q, &CommandQueue::commandFinished);
        const int n = int(CommandQueue::kHistoryLimit) + 5;
        int last = -1;
        for (int i = 0; i < n; ++i) last = rig.q.enqueue("PNVGRST,W");
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), n, 20000);
        QCOMPARE(rig.q.history().size(), CommandQueue::kHistoryLimit);
        QCOMPARE(rig.q.history().last().id, last);
        QCOMPARE(rig.q.history().first().id, last - int(CommandQueue::kHistoryLimit) + 1);
        QCOMPARE(rig.link.written.size(), n);
    }
};

QTEST_GUILESS_MAIN(TstCommandQueue)
#include "tst_command_queue.moc"
