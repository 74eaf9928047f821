// BaudDetector against a fake line that talks only at one speed (garbage at the others): settles
// on that speed — found by its sentences, or by its RTCM 3 frames on a port that carries only
// corrections — and says "no data" or "wrong framing?" when no speed works.
#include "core/sentence_builder.h"
#include "fake_transport.h"
#include "link/baud_detector.h"
#include "rate_rows.h"
#include "rtcm/rtcm_encoder.h"
#include "run_to_finish.h"

#include <QTest>
#include <QTimer>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::FakeTransport;

namespace {

// An RTCM 3 station message (1005), a base's corrections port's usual content.
QByteArray stationFrame() {
    rtcm::StationArp a;
    a.station = 7;
    a.gps = true;
    a.x = 2846000.1;
    a.y = 2190000.5;
    a.z = 5249000.9;
    return QByteArray::fromStdString(rtcm::encodeStationArp(a));
}

// Feeds the transport every 50 ms: a valid GGA (or, `rtcm`, an RTCM 3 frame) at `rightBaud`,
// line noise at other speeds.
class FakeReceiver {
public:
    FakeReceiver(FakeTransport &t, int rightBaud, bool silent = false, bool rtcm = false) : t_(t) {
        QObject::connect(&timer_, &QTimer::timeout, [this, rightBaud, silent, rtcm] {
            if (silent) return;
            if (t_.baud() == rightBaud && rtcm)
                t_.feed(stationFrame());
            else if (t_.baud() == rightBaud)
                t_.feed(QByteArray::fromStdString(
                                buildSentence("GPGGA,100000.00,5540.0000,N,03730.0000,E,1,08,"
                                              "0.9,150.0,M,14.0,M,,")) +
                        "\r\n");
            else
                t_.feed(QByteArray("\xf3$\x9a\x12GP\xe1*\r\n\x80\x7f", 13));
        });
        timer_.start(50);
    }

private:
    FakeTransport &t_;
    QTimer timer_;
};

// A fake line at 9600 baud with `FakeReceiver(link, rightBaud, silent)` on it, and a baud
// detector on the line listening `listenMs` at each rate of `candidates` (its own list when
// empty).
struct Detection {
    FakeTransport link{9600};
    FakeReceiver rx;
    SentenceStream stream{&link, gnss::test::builtinRegistry()};
    BaudDetector d{&stream};

    Detection(int rightBaud, bool silent, const QList<int> &candidates, int listenMs,
              bool rtcm = false)
        : rx(openedFirst(link), rightBaud, silent, rtcm) {
        if (!candidates.isEmpty()) d.setCandidates(candidates);
        d.setListenMs(listenMs);
    }
    // Runs the detection; whether it finished within `ms`.
    bool run(int ms) { return gnss::test::runToFinish(d, ms); }

private:
    static FakeTransport &openedFirst(FakeTransport &t) {
        t.open();
        return t;
    }
};

} // namespace

class TstBaudDetector : public QObject {
    Q_OBJECT
private slots:
    void settlesOnTheRateThatGivesValidSentences_data() { gnss::link::test::everyRateRows(); }
    void settlesOnTheRateThatGivesValidSentences() {
        QFETCH(int, rate);
        Detection detection(rate, false, {}, 200);
        QVERIFY(detection.run(10000));
        const BaudDetector &d = detection.d;
        const FakeTransport &link = detection.link;
        QVERIFY2(d.result().found, qPrintable(d.result().error));
        QCOMPARE(d.result().baud, rate);
        QCOMPARE(link.baud(), rate);
        QCOMPARE(d.result().tried.front().baud, 9600); // the current rate first
    }

    // A port that carries RTCM 3 only (a base's COM2): found by its CRC-valid frames.
    void anRtcmOnlyPortIsFoundByItsFrames_data() { gnss::link::test::everyRateRows(); }
    void anRtcmOnlyPortIsFoundByItsFrames() {
        QFETCH(int, rate);
        Detection detection(rate, false, {}, 200, true);
        QVERIFY(detection.run(10000));
        const BaudDetector &d = detection.d;
        QVERIFY2(d.result().found, qPrintable(d.result().error));
        QCOMPARE(d.result().baud, rate);
        QCOMPARE(d.result().tried.back().validSentences, 0);
        QVERIFY(d.result().tried.back().rtcmFrames >= 2);
    }

    void silenceSaysNoDataAtAnyRate() {
        Detection detection(0, true, {9600, 115200}, 100);
        QVERIFY(detection.run(5000));
        const BaudDetector &d = detection.d;
        const FakeTransport &link = detection.link;
        QVERIFY(!d.result().found);
        QVERIFY2(d.result().error.startsWith("No data at any rate (tried 9600, 115200 baud)"),
                 qPrintable(d.result().error));
        QCOMPARE(link.baud(), 9600); // left where it was
    }

    void garbageSaysWrongFraming() {
        Detection detection(1, false, {9600, 4800}, 150); // no rate works
        QVERIFY(detection.run(5000));
        const BaudDetector &d = detection.d;
        QVERIFY(!d.result().found);
        QVERIFY2(d.result().error.contains("wrong framing"), qPrintable(d.result().error));
        QVERIFY(d.result().tried[0].bytes > 0);
        QCOMPARE(d.result().tried[0].validSentences, 0);
    }

    void probeIsSentAtEachRate() {
        FakeTransport link(9600);
        link.open();
        SentenceStream stream(&link, gnss::test::builtinRegistry());
        BaudDetector d(&stream);
        d.setCandidates({9600, 4800});
        d.setListenMs(50);
        d.setProbe("$PNVGVER*4E");
        QVERIFY(gnss::test::runToFinish(d, 5000));
        QCOMPARE(link.written.size(), 2);
    }
};

QTEST_GUILESS_MAIN(TstBaudDetector)
#include "tst_baud_detector.moc"
