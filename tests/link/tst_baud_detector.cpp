// BaudDetector against a fake line that talks only at one speed (garbage at the others): settles
// on that speed, and says "no data" or "wrong framing?" when no speed works.
#include "baud_detector.h"
#include "core/sentence_builder.h"
#include "fake_transport.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::FakeTransport;

namespace {

// Feeds the transport every 50 ms: a valid GGA at `rightBaud`, line noise at other speeds.
class FakeReceiver {
public:
    FakeReceiver(FakeTransport &t, int rightBaud, bool silent = false) : t_(t) {
        QObject::connect(&timer_, &QTimer::timeout, [this, rightBaud, silent] {
            if (silent) return;
            if (t_.baud() == rightBaud)
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

} // namespace

class TstBaudDetector : public QObject {
    Q_OBJECT
private slots:
    void settlesOnTheRateThatGivesValidSentences_data() {
        QTest::addColumn<int>("rate");
        for (int r : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
            QTest::newRow(qPrintable(QString::number(r))) << r;
    }
    void settlesOnTheRateThatGivesValidSentences() {
        QFETCH(int, rate);
        FakeTransport link(9600);
        link.open();
        FakeReceiver rx(link, rate);
        SentenceStream stream(&link, gnss::test::builtinRegistry());
        BaudDetector d(&stream);
        d.setListenMs(200);
        QSignalSpy finished(&d, &BaudDetector::finished);
        d.start();
        QVERIFY(finished.wait(10000));
        QVERIFY2(d.result().found, qPrintable(d.result().error));
        QCOMPARE(d.result().baud, rate);
        QCOMPARE(link.baud(), rate);
        QCOMPARE(d.result().tried.front().baud, 9600); // the current rate first
    }

    void silenceSaysNoDataAtAnyRate() {
        FakeTransport link(9600);
        link.open();
        FakeReceiver rx(link, 0, true);
        SentenceStream stream(&link, gnss::test::builtinRegistry());
        BaudDetector d(&stream);
        d.setCandidates({9600, 115200});
        d.setListenMs(100);
        QSignalSpy finished(&d, &BaudDetector::finished);
        d.start();
        QVERIFY(finished.wait(5000));
        QVERIFY(!d.result().found);
        QVERIFY2(d.result().error.startsWith("No data at any rate (tried 9600, 115200 baud)"),
                 qPrintable(d.result().error));
        QCOMPARE(link.baud(), 9600); // left where it was
    }

    void garbageSaysWrongFraming() {
        FakeTransport link(9600);
        link.open();
        FakeReceiver rx(link, 1); // no rate works
        SentenceStream stream(&link, gnss::test::builtinRegistry());
        BaudDetector d(&stream);
        d.setCandidates({9600, 4800});
        d.setListenMs(150);
        QSignalSpy finished(&d, &BaudDetector::finished);
        d.start();
        QVERIFY(finished.wait(5000));
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
        QSignalSpy finished(&d, &BaudDetector::finished);
        d.start();
        QVERIFY(finished.wait(5000));
        QCOMPARE(link.written.size(), 2);
    }
};

QTEST_GUILESS_MAIN(TstBaudDetector)
#include "tst_baud_detector.moc"
