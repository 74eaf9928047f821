// The other sources behind the same interface: the in-process simulator (baud detection, vendor
// detection and a command without any serial port) and a TCP client against gnss-sim --tcp.
#include "builtin/dialects.h"
#include "builtin_registry.h"
#include "common/simulator_transport.h"
#include "link/baud_detector.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "link/sentence_stream.h"
#include "link/tcp_transport.h"
#include "link/vendor_detector.h"
#include "local_port.h"
#include "loop_watch.h"
#include "run_to_finish.h"
#include "sim_tcp_process.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QThread>
#include <QTimer>

using namespace gnss;
using namespace gnss::link;

namespace {

using gnss::test::closedPort;

// A TCP port on 127.0.0.1 that takes no new connection: it listens with a backlog of one and
// that one place is taken, so further connection attempts get no answer at all.
struct SilentListener {
    int fd = -1;
    QList<int> fillers;
    quint16 port = 0;
    SilentListener() {
        fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t len = sizeof a;
        if (::bind(fd, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0 || ::listen(fd, 0) != 0 ||
            ::getsockname(fd, reinterpret_cast<sockaddr *>(&a), &len) != 0)
            return;
        port = ntohs(a.sin_port);
        for (int i = 0; i < 3; ++i) { // fill the queue (never accepted)
            const int c = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
            ::connect(c, reinterpret_cast<sockaddr *>(&a), sizeof a);
            fillers.append(c);
        }
        QTest::qWait(100);
    }
    ~SilentListener() {
        for (int c : fillers) ::close(c);
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

class TstSources : public QObject {
    Q_OBJECT
private slots:
    void inProcessSimulatorIsDetectedAndCommanded() {
        SimulatorTransport sim(gnss::sim::builtinSimulators(), QStringLiteral("nvs"), 3,
                               9600); // receiver at 115200
        QVERIFY2(sim.open(), qPrintable(sim.errorString()));
        SentenceStream stream(&sim, gnss::test::builtinRegistry());
        BaudDetector baud(&stream);
        baud.setListenMs(500);
        QVERIFY(gnss::test::runToFinish(baud, 15000));
        QVERIFY2(baud.result().found, qPrintable(baud.result().error));
        QCOMPARE(baud.result().baud, 115200);

        VendorDetector vendor(&stream);
        QVERIFY(gnss::test::runToFinish(vendor, 10000));
        QCOMPARE(vendor.result().dialect, QStringLiteral("nvs"));
        QVERIFY(!vendor.result().firmware.isEmpty());

        CommandQueue q(&sim, &stream);
        q.setDialect(gnss::test::builtinRegistry().find("nvs"));
        q.enqueue("PNVGVER");
        QTRY_COMPARE_WITH_TIMEOUT(q.history().size(), 1, 5000);
        QCOMPARE(int(q.history().first().outcome), int(CommandOutcome::Accepted));
    }

    void tcpClientReadsGnssSimAndNoticesItLeaving() {
        if (link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        link::test::SimTcpProcess sim({"--dialect", "nmea"});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        TcpTransport tcp(QStringLiteral("127.0.0.1"), sim.port);
        QVERIFY2(tcp.open(), qPrintable(tcp.errorString()));
        QByteArray got;
        connect(&tcp, &Transport::bytesReceived, [&](const QByteArray &b) { got += b; });
        QTRY_VERIFY_WITH_TIMEOUT(got.contains("GGA,"), 5000);
        QSignalSpy state(&tcp, &Transport::stateChanged);
        sim.stop();
        QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Transport::State::Lost, 5000);
        QVERIFY(!tcp.errorString().isEmpty());
    }

    // What is read is handed on in chunks of at most kReadChunk, however much waits in the
    // kernel (here several megabytes, sent while the loop was busy): memory does not follow
    // the longest stall of whatever consumes it.
    void tcpReadsInBoundedChunks() {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        TcpTransport tcp(QStringLiteral("127.0.0.1"), server.serverPort());
        QVERIFY(tcp.open());
        QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), 5000);
        QTcpSocket *peer = server.nextPendingConnection();
        QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Transport::State::Open, 5000);
        qint64 got = 0, largest = 0;
        connect(&tcp, &Transport::bytesReceived, [&](const QByteArray &b) {
            got += b.size();
            largest = std::max<qint64>(largest, b.size());
        });
        const QByteArray block(1 << 20, 'x');
        constexpr qint64 kTotal = 8 << 20;
        for (qint64 sent = 0; sent < kTotal; sent += block.size()) peer->write(block);
        // The bytes reach the kernel's buffers while nothing reads them.
        for (int i = 0; i < 20 && peer->bytesToWrite() > 0; ++i) {
            peer->waitForBytesWritten(50);
            QThread::msleep(20);
        }
        QTRY_COMPARE_WITH_TIMEOUT(got, kTotal, 10000);
        QVERIFY2(largest <= TcpTransport::kReadChunk, QByteArray::number(largest));
    }

    void tcpConnectsInTheBackgroundAndSaysWhyItFailed() {
        gnss::test::LoopWatch watch;
        TcpTransport tcp(QStringLiteral("127.0.0.1"), closedPort());
        QSignalSpy errors(&tcp, &Transport::errorOccurred);
        QElapsedTimer t;
        t.start();
        QVERIFY(tcp.open());
        QVERIFY2(t.elapsed() < 100, QByteArray::number(t.elapsed())); // returned at once
        QCOMPARE(tcp.state(), Transport::State::Connecting);
        QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Transport::State::Closed, 5000);
        QCOMPARE(errors.size(), 1);
        QVERIFY2(tcp.errorString().contains("127.0.0.1"), qPrintable(tcp.errorString()));
        QVERIFY2(tcp.errorString().contains("refused", Qt::CaseInsensitive),
                 qPrintable(tcp.errorString()));
        QVERIFY2(watch.worst < 200, QByteArray::number(watch.worst));
    }

    void aSilentHostTimesOutWithoutBlocking() {
        // A listening socket whose accept queue is full never answers a new connection (the
        // kernel drops the SYN): the attempt is given up after the connect timeout, and the
        // event loop runs throughout.
        SilentListener silent;
        QVERIFY(silent.port > 0);
        gnss::test::LoopWatch watch;
        TcpTransport tcp(QStringLiteral("127.0.0.1"), silent.port);
        tcp.setConnectTimeout(400);
        QElapsedTimer t;
        t.start();
        QVERIFY(tcp.open());
        QVERIFY(t.elapsed() < 100);
        QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Transport::State::Closed, 3000);
        QVERIFY2(t.elapsed() >= 350, QByteArray::number(t.elapsed()));
        QVERIFY2(tcp.errorString().contains("no answer"), qPrintable(tcp.errorString()));
        QVERIFY2(watch.worst < 200, QByteArray::number(watch.worst));
    }

    void aConnectionRetriesAClosedPortWithGrowingWaits() {
        gnss::test::LoopWatch watch;
        Connection conn(std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), closedPort()),
                        gnss::test::builtinRegistry());
        conn.setReconnectDelays(50, 200);
        QList<int> waits;
        connect(&conn, &Connection::openFailed,
                [&](const QString &, int retryMs) { waits.append(retryMs); });
        QVERIFY(conn.open());
        QTRY_VERIFY_WITH_TIMEOUT(waits.size() >= 5, 5000);
        QCOMPARE(waits.mid(0, 5), (QList<int>{50, 100, 200, 200, 200}));
        QVERIFY(conn.isReconnecting());
        conn.close();
        QVERIFY(!conn.isReconnecting());
        QVERIFY2(watch.worst < 200, QByteArray::number(watch.worst));
    }

    void commandsQueuedWhileConnectingWaitForTheLink() {
        if (link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        link::test::SimTcpProcess sim({"--dialect", "nvs"});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        Connection conn(std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), sim.port),
                        gnss::test::builtinRegistry());
        QVERIFY(conn.open());
        conn.commands()->setDialect(gnss::test::builtinRegistry().find("nvs"));
        conn.commands()->enqueue("PNVGVER"); // before the socket has connected
        QTRY_COMPARE_WITH_TIMEOUT(conn.commands()->history().size(), 1, 5000);
        QCOMPARE(int(conn.commands()->history().first().outcome), int(CommandOutcome::Accepted));
    }

    void hostPortIsParsed() {
        QString host;
        quint16 port = 0;
        QVERIFY(TcpTransport::parseHostPort("192.168.1.5:4001", host, port));
        QCOMPARE(host, QStringLiteral("192.168.1.5"));
        QCOMPARE(port, quint16(4001));
        QVERIFY(TcpTransport::parseHostPort("[::1]:10110", host, port));
        QCOMPARE(host, QStringLiteral("::1"));
        QVERIFY(!TcpTransport::parseHostPort("host", host, port));
        QVERIFY(!TcpTransport::parseHostPort("host:99999", host, port));
    }
};

QTEST_GUILESS_MAIN(TstSources)
#include "tst_sources.moc"
