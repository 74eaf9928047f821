// The reconnect policy on a fake clock: waits double from 2 s to 60 s, a minute of data makes
// the next wait 2 s again, less than a minute does not.
#include "ntrip/reconnect_policy.h"

#include <QTest>

using namespace gnss::ntrip;

class TstReconnectPolicy : public QObject {
    Q_OBJECT
private slots:
    void waitsDoubleFromTwoToSixtySeconds() {
        ReconnectPolicy p;
        QList<qint64> waits;
        for (int i = 0; i < 8; ++i) waits.append(p.nextDelayMs());
        QCOMPARE(waits, (QList<qint64>{2000, 4000, 8000, 16000, 32000, 60000, 60000, 60000}));
        QCOMPARE(p.failures(), 8);
    }

    void aMinuteOfDataMakesTheNextWaitShortAgain_data() {
        QTest::addColumn<qint64>("dataFor");
        QTest::addColumn<qint64>("nextWait");
        QTest::newRow("a minute of data: healthy") << qint64(60000) << qint64(2000);
        QTest::newRow("59.9 s of data: not yet") << qint64(59900) << qint64(16000);
        QTest::newRow("one burst of data: not yet") << qint64(0) << qint64(16000);
    }
    void aMinuteOfDataMakesTheNextWaitShortAgain() {
        QFETCH(qint64, dataFor);
        QFETCH(qint64, nextWait);
        ReconnectPolicy p;
        qint64 now = 1000000; // a fake monotonic clock, ms
        p.nextDelayMs();      // 2 s
        p.nextDelayMs();      // 4 s
        p.nextDelayMs();      // 8 s
        for (qint64 t = 0; t <= dataFor; t += 100) p.dataReceived(now + t);
        p.dataReceived(now + dataFor);
        QCOMPARE(p.nextDelayMs(), nextWait);
    }

    void dataOfAnEarlierConnectionDoesNotCount() {
        // 40 s of data, a drop, 30 s more: not one minute on one connection.
        ReconnectPolicy p;
        p.nextDelayMs();
        p.dataReceived(0);
        p.dataReceived(40000);
        QCOMPARE(p.nextDelayMs(), qint64(4000));
        p.dataReceived(45000);
        p.dataReceived(75000);
        QCOMPARE(p.nextDelayMs(), qint64(8000));
    }

    void shortDelaysForTests() {
        ReconnectPolicy p({50, 200, 1000});
        QList<qint64> waits;
        for (int i = 0; i < 5; ++i) waits.append(p.nextDelayMs());
        QCOMPARE(waits, (QList<qint64>{50, 100, 200, 200, 200}));
        p.reset();
        QCOMPARE(p.nextDelayMs(), qint64(50));
        ReconnectPolicy zero({0, 10, 1000});
        QCOMPARE(zero.nextDelayMs(), qint64(0));
        QCOMPARE(zero.nextDelayMs(), qint64(1));
    }
};

QTEST_APPLESS_MAIN(TstReconnectPolicy)
#include "tst_reconnect_policy.moc"
