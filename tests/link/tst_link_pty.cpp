// End to end: the link layer against gnss-sim on pseudo-terminals, through the real QSerialPort.
// Baud detection from every rate, vendor detection per dialect, command outcomes (accepted,
// refused, timed out via the simulator's faults), a baud change round trip, reconnect after the
// simulator hangs up and comes back (same device path, now a new pseudo-terminal), recording
// byte-exact.
#include "builtin/dialects.h"
#include "builtin_registry.h"
#include "link/baud_detector.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "link/recording.h"
#include "link/sentence_stream.h"
#include "link/serial_transport.h"
#include "link/vendor_detector.h"
#include "queue_checks.h"
#include "rate_rows.h"
#include "run_to_finish.h"
#include "sim_process.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::SimProcess;

namespace {

// The real serial port on an NV08C-RTK's device at its 115200 baud, read as sentences, with a
// command queue that speaks nvs.
struct NvsCommandLink {
    SerialTransport port;
    SentenceStream stream{&port, gnss::test::builtinRegistry()};
    CommandQueue commands{&port, &stream};
    explicit NvsCommandLink(const QString &device) : port(SerialSettings{device, 115200}) {
        commands.setDialect(gnss::test::builtinRegistry().find("nvs"));
    }
};

} // namespace

class TstLinkPty : public QObject {
    Q_OBJECT
private slots:
    void baudDetectionFindsTheReceiverAtEveryRate_data() { gnss::link::test::everyRateRows(); }
    void baudDetectionFindsTheReceiverAtEveryRate() {
        QFETCH(int, rate);
        SimProcess sim({"--dialect", "nvs", "--baud", QString::number(rate), "--seed", "2"});
        REQUIRE_SIM(sim);
        SerialTransport port(SerialSettings{sim.device, 9600});
        QVERIFY2(port.open(), qPrintable(port.errorString()));
        SentenceStream stream(&port, gnss::test::builtinRegistry());
        BaudDetector d(&stream);
        d.setListenMs(500); // NVS: 5 Hz
        QVERIFY(gnss::test::runToFinish(d, 20000));
        QVERIFY2(d.result().found, qPrintable(d.result().error));
        QCOMPARE(d.result().baud, rate);
        QCOMPARE(port.baud(), rate);
    }

    void vendorDetectionNamesEachDialect_data() {
        QTest::addColumn<QString>("dialect");
        for (const char *d : {"nvs", "geostar", "nemerix", "nmea"}) QTest::newRow(d) << d;
    }
    void vendorDetectionNamesEachDialect() {
        QFETCH(QString, dialect);
        SimProcess sim({"--dialect", dialect, "--baud", "38400"});
        REQUIRE_SIM(sim);
        SerialTransport port(SerialSettings{sim.device, 38400});
        QVERIFY2(port.open(), qPrintable(port.errorString()));
        SentenceStream stream(&port, gnss::test::builtinRegistry());
        VendorDetector v(&stream);
        QVERIFY(gnss::test::runToFinish(v, 10000));
        const VendorIdentity &id = v.result();
        QVERIFY2(id.found, qPrintable(id.error));
        QCOMPARE(id.dialect, dialect);
        if (dialect != "nmea") { // a plain NMEA receiver has no identity sentence
            QVERIFY2(!id.reply.isEmpty(), qPrintable(id.method));
            QVERIFY2(!id.firmware.isEmpty(), qPrintable(id.replyJson));
        }
    }

    void commandOutcomesThroughTheSimulator() {
        SimProcess sim({"--dialect", "nvs", "--faults", "noreply=PNVGCFG"});
        REQUIRE_SIM(sim);
        NvsCommandLink link(sim.device);
        QVERIFY2(link.port.open(), qPrintable(link.port.errorString()));
        CommandQueue &q = link.commands;
        q.enqueue("PNVGVER");
        q.enqueue("PNVGRTK,PVTRATE,99"); // out of range: the reply carries the rate in force
        CommandOptions quick;
        quick.timeoutMs = 300;
        quick.retries = 1;
        q.enqueue("PNVGCFG,W", quick); // the simulator's fault: never answered
        QVERIFY(waitForHistory(q, 3, 10000));
        QCOMPARE(q.history()[0].outcome, CommandOutcome::Accepted);
        QVERIFY(q.history()[0].replies.first().startsWith("$PNVGVER,NVS"));
        QCOMPARE(q.history()[1].outcome, CommandOutcome::Refused);
        QVERIFY2(q.history()[1].detail.contains("PNVGRTK"), qPrintable(q.history()[1].detail));
        QCOMPARE(q.history()[2].outcome, CommandOutcome::TimedOut);
        QCOMPARE(q.history()[2].attempts, 2);
    }

    void baudChangeRoundTrip() {
        SimProcess sim({"--dialect", "nvs"});
        REQUIRE_SIM(sim);
        NvsCommandLink link(sim.device);
        QVERIFY2(link.port.open(), qPrintable(link.port.errorString()));
        CommandQueue &q = link.commands;
        q.enqueue("PNVGRZA,1,38400,1");
        QVERIFY(waitForHistory(q, 1, 10000));
        QCOMPARE(q.history()[0].outcome, CommandOutcome::Accepted);
        QCOMPARE(q.history()[0].baudAfter, 38400);
        QCOMPARE(link.port.baud(), 38400);
        // Commands work at the new speed, and the way back works too.
        q.enqueue("PNVGVER");
        q.enqueue("PNVGRZA,1,115200,1");
        QVERIFY(waitForHistory(q, 3, 10000));
        QCOMPARE(q.history()[1].outcome, CommandOutcome::Accepted);
        QCOMPARE(q.history()[2].outcome, CommandOutcome::Accepted);
        QCOMPARE(link.port.baud(), 115200);
    }

    void reconnectAfterTheSimulatorHangsUpAndComesBack() {
        QTemporaryDir dir;
        const QString link = dir.filePath("ttyGNSS"); // a stable name for a changing device
        SimProcess first({"--dialect", "nmea", "--faults", "hangup=2"});
        REQUIRE_SIM(first);
        QVERIFY(QFile::link(first.device, link));

        Connection conn(std::make_unique<SerialTransport>(SerialSettings{link, 9600}),
                        gnss::test::builtinRegistry());
        conn.setReconnectDelays(200, 800); // the waits grow (tst_sources); here they stay short
        const QString log = dir.filePath("run.nmea");
        QVERIFY(conn.startRecording(log));
        QByteArray received;
        connect(conn.transport(), &Transport::bytesReceived,
                [&](const QByteArray &b) { received += b; });
        QSignalSpy lost(&conn, &Connection::linkLost), back(&conn, &Connection::linkRestored);
        QVERIFY(conn.open());
        QVERIFY2(lost.wait(8000), "the hang-up was not noticed");
        // The device's name goes with it, as an unplugged USB receiver's does (the freed
        // pseudo-terminal number may be another suite's next one).
        QFile::remove(link);
        QVERIFY(conn.isReconnecting());
        const qsizetype before = received.size();
        QVERIFY(before > 0);

        QTest::qWait(1500); // a couple of failed attempts while nothing is there
        SimProcess second({"--dialect", "nmea", "--seed", "7"});
        QVERIFY(second.ok());
        QVERIFY(QFile::link(second.device, link));
        // Generous: a loaded machine starts the second simulator slowly (not a timing test).
        // The failure message says how far the retries got, should this ever fail again.
        QSignalSpy attempts(&conn, &Connection::reconnectAttempt);
        QString lastFailure;
        connect(&conn, &Connection::openFailed, this,
                [&](const QString &why, int) { lastFailure = why; });
        QTRY_VERIFY2_WITH_TIMEOUT(
                back.count() > 0,
                qPrintable(QStringLiteral("did not reconnect: %1 attempts since the device came "
                                          "back, last failure '%2', "
                                          "transport %3")
                                   .arg(attempts.count())
                                   .arg(lastFailure,
                                        conn.transport()->isOpen() ? "open" : "not open")),
                20000);
        QTRY_VERIFY_WITH_TIMEOUT(received.size() > before + 200, 5000);
        conn.close();
        conn.stopRecording();

        Recording r;
        QString error;
        QVERIFY2(loadRecording(log, r, error), qPrintable(error));
        QCOMPARE(r.bytes, received); // bytes logged == bytes received, across the gap
        int gaps = 0;
        for (const auto &e : r.events) gaps += e.kind == RecordedEvent::Kind::Gap;
        // A mark for every loss and every return: lost, back (on a loaded machine the fresh
        // device can drop once more while the simulator starts; then the marks say so too).
        QVERIFY(back.count() >= 1);
        QCOMPARE(gaps, int(lost.count() + back.count()));
    }

    // A receiver that hangs with its port open (silence=5@2: no output, no replies) is taken as
    // lost after the silence limit, opened again, and heard once it talks; the recording marks
    // both and keeps every byte.
    void aHungReceiverIsOpenedAgain() {
        QTemporaryDir dir;
        SimProcess sim({"--dialect", "nvs", "--faults", "silence=5@2"});
        REQUIRE_SIM(sim);
        Connection conn(std::make_unique<SerialTransport>(SerialSettings{sim.device, 115200}),
                        gnss::test::builtinRegistry());
        conn.setReconnectDelays(200, 800);
        conn.setSilenceLimit(2000);
        const QString log = dir.filePath("hung.nmea");
        QVERIFY(conn.startRecording(log));
        QByteArray received;
        connect(conn.transport(), &Transport::bytesReceived,
                [&](const QByteArray &b) { received += b; });
        QSignalSpy lost(&conn, &Connection::linkLost), back(&conn, &Connection::linkRestored);
        QVERIFY(conn.open());
        QTRY_VERIFY_WITH_TIMEOUT(received.size() > 0, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(conn.silentMs() >= 1000, 8000);
        QVERIFY2(lost.wait(8000), "the silence was not noticed");
        QVERIFY2(lost.first().at(0).toString().contains("no data"),
                 qPrintable(lost.first().at(0).toString()));
        QTRY_VERIFY_WITH_TIMEOUT(back.count() > 0, 10000);
        const qsizetype before = received.size();
        QTRY_VERIFY_WITH_TIMEOUT(received.size() > before + 200, 10000); // talking again
        QVERIFY(conn.silentMs() < 2000);
        conn.close();
        conn.stopRecording();
        Recording r;
        QString error;
        QVERIFY2(loadRecording(log, r, error), qPrintable(error));
        QCOMPARE(r.bytes, received);
        int gaps = 0;
        for (const auto &e : r.events) gaps += e.kind == RecordedEvent::Kind::Gap;
        QCOMPARE(gaps, int(lost.count() + back.count()));
    }

    void recordingIsByteExact() {
        SimProcess sim({"--dialect", "nvs", "--faults", "binary=0.3,badcs=0.05"});
        REQUIRE_SIM(sim);
        QTemporaryDir dir;
        Connection conn(std::make_unique<SerialTransport>(SerialSettings{sim.device, 115200}),
                        gnss::test::builtinRegistry());
        const QString log = dir.filePath("rec.nmea");
        QVERIFY(conn.startRecording(log));
        QByteArray received;
        connect(conn.transport(), &Transport::bytesReceived,
                [&](const QByteArray &b) { received += b; });
        QVERIFY(conn.open());
        conn.commands()->enqueue("PNVGVER");
        QTest::qWait(2000);
        conn.close();
        conn.stopRecording();
        Recording r;
        QString error;
        QVERIFY2(loadRecording(log, r, error), qPrintable(error));
        QVERIFY(received.size() > 1000);
        QCOMPARE(r.bytes, received);
        QCOMPARE(qint64(conn.bytesReceived()), qint64(received.size()));
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].text, QStringLiteral("$PNVGVER*4E"));
    }
};

QTEST_GUILESS_MAIN(TstLinkPty)
#include "tst_link_pty.moc"
