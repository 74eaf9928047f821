// ReplayTransport: a recording played back byte-exact, at its recorded pace (host timestamps or
// sentence times) times a speed factor, paused, stepped and sought.
#include "core/sentence_builder.h"
#include "link/recorder.h"
#include "link/replay_transport.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>

using namespace gnss;
using namespace gnss::link;

namespace {

QByteArray line(const std::string &body) {
    return QByteArray::fromStdString(buildSentence(body)) + "\r\n";
}

QByteArray epoch(int second) {
    const std::string t = "1000" + std::string(second < 10 ? "0" : "") + std::to_string(second);
    return line("GPGGA," + t + ".00,5540.0000,N,03730.0000,E,1,08,0.9,150.0,M,14.0,M,,") +
           line("GPGSA,A,3,01,02,03,04,,,,,,,,,1.8,0.9,1.5") +
           line("GPRMC," + t + ".00,A,5540.0000,N,03730.0000,E,0.0,0.0,150324,,,A");
}

// A recording of three chunks, 500 ms apart (host time), one command sent after the first.
QString makeRecorded(const QTemporaryDir &dir) {
    const QString path = dir.filePath("rec.nmea");
    qint64 now = 1710496800000;
    Recorder rec(nullptr, [&] { return now; });
    rec.open(path);
    rec.received(epoch(0));
    rec.sent("$PNVGVER*4E\r\n");
    now += 500;
    rec.received(epoch(1));
    now += 500;
    rec.received(epoch(2));
    return path;
}

// A plain NMEA log (no index): sentence times one second apart.
QString makePlain(const QTemporaryDir &dir, int epochs) {
    const QString path = dir.filePath("plain.nmea");
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    for (int i = 0; i < epochs; ++i) f.write(epoch(i));
    return path;
}

struct Arrivals {
    QByteArray bytes;
    QList<qint64> at;
    QElapsedTimer clock;
    void attach(ReplayTransport &r) {
        clock.start();
        // Pace is measured from the moment the log is open (it is timed in the background).
        QObject::connect(&r, &Transport::stateChanged, [this](Transport::State s) {
            if (s == Transport::State::Open) clock.restart();
        });
        QObject::connect(&r, &Transport::bytesReceived, [this](const QByteArray &b) {
            bytes += b;
            at.append(clock.elapsed());
        });
    }
};

// A plain log of five epochs, to be opened paused, delivering into `got`.
struct PausedReplay {
    QTemporaryDir dir;
    ReplayTransport r{makePlain(dir, 5)};
    Arrivals got;
    PausedReplay() {
        got.attach(r);
        r.pause();
    }
};

// Plays `r` at `speed` to its end into `got`; once it is open, it paces by `timing` a log of
// `duration` seconds.
void playToTheEnd(ReplayTransport &r, double speed, Arrivals &got, ReplayTransport::Timing timing,
                  double duration) {
    r.setSpeed(speed);
    got.attach(r);
    QSignalSpy finished(&r, &ReplayTransport::finished);
    QVERIFY(r.open());
    QTRY_VERIFY(r.isOpen());
    QCOMPARE(r.timing(), timing);
    QCOMPARE(r.duration(), duration);
    QVERIFY(finished.wait(3000));
}

} // namespace

class TstReplay : public QObject {
    Q_OBJECT
private slots:
    void replayIsByteExactAndReportsSentCommands() {
        QTemporaryDir dir;
        const QString path = makeRecorded(dir);
        ReplayTransport r(path, ReplayTransport::Timing::AsFast);
        Arrivals got;
        QList<RecordedEvent> events;
        connect(&r, &ReplayTransport::recordedEvent,
                [&](const RecordedEvent &e) { events.append(e); });
        QSignalSpy finished(&r, &ReplayTransport::finished);
        got.attach(r);
        QVERIFY(r.open());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 2000);
        QCOMPARE(got.bytes, epoch(0) + epoch(1) + epoch(2));
        QCOMPARE(events.size(), 1);
        QCOMPARE(events[0].text, QStringLiteral("$PNVGVER*4E"));
        QVERIFY(!r.write("$PNVGVER*4E\r\n")); // a replay takes no commands
    }

    void hostTimestampsSetThePaceTimesTheSpeed() {
        QTemporaryDir dir;
        ReplayTransport r(makeRecorded(dir));
        Arrivals got;
        playToTheEnd(r, 2, got, ReplayTransport::Timing::HostTime, 1.0);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(got.at.size(), 3);
        // 0, 250, 500 ms at twice the speed (timer granularity: 10 ms; loaded machine: +100).
        QVERIFY2(got.at[1] >= 230 && got.at[1] < 400, QByteArray::number(got.at[1]));
        QVERIFY2(got.at[2] >= 480 && got.at[2] < 650, QByteArray::number(got.at[2]));
    }

    void sentenceTimesPaceAPlainLog() {
        QTemporaryDir dir;
        ReplayTransport r(makePlain(dir, 3));
        Arrivals got;
        playToTheEnd(r, 4, got, ReplayTransport::Timing::SentenceTime, 2.0);
        if (QTest::currentTestFailed()) return;
        // Each epoch's three sentences arrive together, 250 ms apart at four times the speed.
        QCOMPARE(got.at.size(), 3);
        QVERIFY(got.bytes.startsWith(epoch(0)));
        QVERIFY2(got.at[2] >= 480 && got.at[2] < 650, QByteArray::number(got.at[2]));
        QCOMPARE(got.bytes, epoch(0) + epoch(1) + epoch(2));
    }

    void pauseHoldsAndStepDeliversOneEpoch() {
        PausedReplay paused;
        auto &[dir, r, got] = paused;
        QVERIFY(r.open());
        QTRY_VERIFY(r.isOpen());
        QTest::qWait(100);
        QVERIFY(got.bytes.isEmpty());
        QVERIFY(r.step());
        QCOMPARE(got.bytes, epoch(0));
        QVERIFY(r.step());
        QCOMPARE(got.bytes, epoch(0) + epoch(1));
        QCOMPARE(r.position(), 1.0);
    }

    void seekStartsAtTheFirstBytesAtOrAfterTheTime() {
        PausedReplay paused;
        auto &[dir, r, got] = paused;
        QVERIFY(r.open());
        QTRY_VERIFY(r.isOpen());
        r.seek(3.0);
        QVERIFY(r.step());
        QCOMPARE(got.bytes, epoch(3));
        r.seek(0.5); // between epochs: the next one
        QVERIFY(r.step());
        QCOMPARE(got.bytes, epoch(3) + epoch(1));
        // Seeking back and playing fast gives the rest, byte-exact.
        got.bytes.clear();
        QSignalSpy finished(&r, &ReplayTransport::finished);
        r.seek(2.0);
        r.setSpeed(100);
        r.resume();
        QVERIFY(finished.wait(2000));
        QCOMPARE(got.bytes, epoch(2) + epoch(3) + epoch(4));
    }

    void missingFileSaysWhich() {
        ReplayTransport r(QStringLiteral("/nonexistent/x.nmea"));
        QVERIFY(!r.open());
        QVERIFY(r.errorString().contains("/nonexistent/x.nmea"));
    }

    void aBigLogOpensInTheBackgroundWithProgress() {
        // 40 MB of epochs: open() returns at once (Connecting), progress comes, then Open and
        // the bytes, byte-exact, without the file being read on this thread.
        QTemporaryDir dir;
        const QString path = dir.filePath("big.nmea");
        QByteArray all;
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QByteArray block;
            for (int i = 0; i < 60; ++i) block += epoch(i);
            while (all.size() < 40'000'000) all += block;
            f.write(all);
        }
        ReplayTransport r(path, ReplayTransport::Timing::AsFast);
        QSignalSpy progress(&r, &ReplayTransport::openingProgress);
        QSignalSpy finished(&r, &ReplayTransport::finished);
        Arrivals got;
        got.attach(r);
        QElapsedTimer t;
        t.start();
        QVERIFY(r.open());
        const qint64 openMs = t.elapsed();
        QCOMPARE(r.state(), Transport::State::Connecting);
        QVERIFY2(openMs < 200, QByteArray::number(openMs)); // no scan in open() itself
        QTRY_VERIFY_WITH_TIMEOUT(r.isOpen(), 30000);
        QVERIFY(!progress.isEmpty());
        QCOMPARE(progress.last().at(0).toInt(), 100);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        QCOMPARE(got.bytes.size(), all.size());
        QVERIFY(got.bytes == all);
        QVERIFY(got.at.size() > 5); // streamed in pieces, not one block
    }

    void anIndexThatContradictsTheDataFailsAfterOpening() {
        QTemporaryDir dir;
        const QString path = makeRecorded(dir);
        QFile idx(indexPathFor(path));
        QVERIFY(idx.open(QIODevice::Append));
        idx.write("R 1710496801000 999999 10\n");
        idx.close();
        ReplayTransport r(path);
        QSignalSpy errors(&r, &Transport::errorOccurred);
        QVERIFY(r.open());
        QTRY_COMPARE(r.state(), Transport::State::Closed);
        QCOMPARE(errors.size(), 1);
        QVERIFY2(r.errorString().contains(".idx"), qPrintable(r.errorString()));
    }

    void closingWhileOpeningStopsTheWorker() {
        QTemporaryDir dir;
        ReplayTransport r(makePlain(dir, 5));
        QVERIFY(r.open());
        r.close();
        QCOMPARE(r.state(), Transport::State::Closed);
        QTest::qWait(50);
        QCOMPARE(r.state(), Transport::State::Closed); // a late result is not applied
    }

    // open() again before the first finished: the first worker is stopped and its result never
    // applied, so the log plays once, whole.
    void openingAgainWhileOpeningPlaysOnce() {
        QTemporaryDir dir;
        const QString path = makePlain(dir, 5);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray all = f.readAll();
        ReplayTransport r(path, ReplayTransport::Timing::AsFast);
        QSignalSpy finished(&r, &ReplayTransport::finished);
        QSignalSpy progress(&r, &ReplayTransport::openingProgress);
        Arrivals got;
        got.attach(r);
        QVERIFY(r.open());
        QVERIFY(r.open());
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(got.bytes, all);
        const auto full = std::count_if(progress.begin(), progress.end(),
                                        [](const QList<QVariant> &a) { return a[0] == 100; });
        QCOMPARE(full, 1); // one open finished
        QTest::qWait(50);
        QCOMPARE(finished.count(), 1);
        QCOMPARE(got.bytes, all);
    }
};

QTEST_GUILESS_MAIN(TstReplay)
#include "tst_replay.moc"
