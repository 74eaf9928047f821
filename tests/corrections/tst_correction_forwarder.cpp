// CorrectionForwarder: whole RTCM frames only, one write each, never while a command waits for
// its reply; a bounded queue that drops the oldest and counts; nothing but frames goes through.
#include "corrections/correction_forwarder.h"
#include "rtcm_fixtures.h"

#include "core/sentence_builder.h"
#include "fake_transport.h"
#include "link/command_queue.h"
#include "link/sentence_stream.h"
#include "rtcm/rtcm_framer.h"

#include <QTest>

using namespace gnss;
using namespace gnss::link;
using namespace gnss::link::test;
using gnss::corrections::CorrectionForwarder;

namespace {

// Every frame in `bytes`, as written.
QList<QByteArray> framesOf(const QByteArray &bytes) {
    QList<QByteArray> out;
    rtcm::RtcmFramer framer;
    framer.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
                [&](const rtcm::RtcmFrame &f) {
                    out.append(QByteArray(reinterpret_cast<const char *>(f.bytes.data()),
                                          qsizetype(f.bytes.size())));
                });
    return out;
}

QByteArray joined(const QList<QByteArray> &parts) {
    QByteArray all;
    for (const QByteArray &p : parts) all += p;
    return all;
}

struct Link {
    FakeTransport transport{115200};
    SentenceStream stream{&transport, builtinRegistry()};
    CommandQueue queue{&transport, &stream};
    Link() {
        queue.setDialect(builtinRegistry().find("nvs"));
        transport.open();
    }
};

} // namespace

class TstCorrectionForwarder : public QObject {
    Q_OBJECT
private slots:
    void framesCutAnywhereAreWrittenWholeOneWriteEach() {
        Link l;
        CorrectionForwarder f(&l.transport, &l.queue);
        const QByteArray stream = joined(corrections_test::baseEpochs(5));
        const QList<QByteArray> frames = framesOf(stream);
        QVERIFY(frames.size() >= 10);
        // Cut into 7-byte pieces with noise between epochs: frames only, as they were.
        f.feed("ICY 200 OK\r\n\r\n");
        for (qsizetype i = 0; i < stream.size(); i += 7) f.feed(stream.mid(i, 7));
        QCOMPARE(l.transport.written, frames);
        QCOMPARE(f.stats().framesForwarded, std::uint64_t(frames.size()));
        QCOMPARE(f.stats().bytesForwarded, std::uint64_t(stream.size()));
        QCOMPARE(f.stats().bytesSkipped, std::uint64_t(14));
        QCOMPARE(f.stats().framesDropped, std::uint64_t(0));
    }

    void framesWaitWhileACommandAwaitsItsReply() {
        Link l;
        CorrectionForwarder f(&l.transport, &l.queue);
        QVERIFY(l.queue.enqueue("PNVGVER") > 0);
        QTRY_VERIFY(l.queue.isBusy()); // sent from the event loop
        const int commandWrites = int(l.transport.written.size());
        const QByteArray epoch = corrections_test::baseEpochs(1).front();
        f.feed(epoch);
        QCOMPARE(l.transport.written.size(), commandWrites); // held back
        QVERIFY(f.queuedFrames() > 0);
        // The reply ends the command: the frames go out after it, whole.
        l.transport.feed(QByteArray::fromStdString(
                buildSentence("PNVGVER,NVS,RTA,0029,CSM24,0101") + "\r\n"));
        QTRY_VERIFY_WITH_TIMEOUT(!l.queue.isBusy(), 10000);
        QCOMPARE(f.queuedFrames(), 0);
        QCOMPARE(joined(l.transport.written.mid(commandWrites)), epoch);
    }

    void aFullQueueDropsTheOldestAndCounts() {
        Link l;
        l.transport.close(); // the link is down: nothing can be written
        CorrectionForwarder f(&l.transport, &l.queue);
        f.setQueueLimit(2000);
        const QList<QByteArray> epochs = corrections_test::baseEpochs(20);
        for (const QByteArray &e : epochs) f.feed(e);
        QVERIFY(f.queuedBytes() <= 2000);
        QVERIFY(f.stats().framesDropped > 0);
        QCOMPARE(f.stats().framesIn, f.stats().framesDropped + std::uint64_t(f.queuedFrames()));
        // Back up: what is left goes out, and it is the newest.
        l.transport.open();
        QCOMPARE(f.queuedFrames(), 0);
        const QByteArray all = joined(epochs);
        QVERIFY(all.endsWith(joined(l.transport.written)));
    }

    // A line slower than the stream: frames wait in the forwarder's bounded queue, not in the
    // port's buffer, and go out as that buffer empties.
    void aFullPortBufferHoldsFramesBack() {
        Link l;
        CorrectionForwarder f(&l.transport, &l.queue);
        l.transport.pendingWrite = 4000; // the port still has 4 KB to send
        const QByteArray epoch = corrections_test::baseEpochs(1).front();
        f.feed(epoch);
        QVERIFY(l.transport.written.isEmpty());
        QVERIFY(f.queuedFrames() > 0);
        l.transport.pendingWrite = 0; // sent
        QTRY_COMPARE(f.queuedFrames(), 0);
        QCOMPARE(joined(l.transport.written), epoch);
    }

    void aCorruptFrameIsNotForwarded() {
        Link l;
        CorrectionForwarder f(&l.transport, &l.queue);
        QByteArray epoch = corrections_test::baseEpochs(1).front();
        const QList<QByteArray> frames = framesOf(epoch);
        QVERIFY(frames.size() >= 2);
        epoch[5] = char(epoch[5] ^ 0x10); // inside the first frame's payload
        f.feed(epoch);
        QCOMPARE(l.transport.written, frames.mid(1));
        QVERIFY(f.stats().crcFailures >= 1);
    }
};

QTEST_GUILESS_MAIN(TstCorrectionForwarder)
#include "tst_correction_forwarder.moc"
