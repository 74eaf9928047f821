// RawStreamServer on 127.0.0.1:0: every client gets the same bytes, exactly (NMEA and RTCM
// alike); what clients send is read and ignored; the client list; a client that does not read
// is dropped while the other gets everything; a client the user drops.
#include "serve/raw_stream_server.h"
#include "serve_test_client.h"

#include <QCryptographicHash>
#include <QSignalSpy>

using namespace gnss::serve;
using namespace serve_test;

class TstRawStreamServer : public QObject {
    Q_OBJECT
private slots:
    void everyClientGetsTheSameBytes() {
        RawStreamServer server;
        QVERIFY(server.listen());
        QCOMPARE(server.address().toString(), QStringLiteral("127.0.0.1"));
        QSignalSpy came(&server, &RawStreamServer::clientConnected);
        TestClient a(server.port()), b(server.port());
        QTRY_COMPARE_WITH_TIMEOUT(came.size(), 2, 3000);
        QByteArray sent;
        for (const QByteArray &e : corrections_test::baseEpochs(3)) {
            const QByteArray bytes = "$GPGSV,1,1,00*79\r\n" + e + QByteArray("\x00\xff", 2);
            server.publish(bytes);
            sent += bytes;
        }
        // Whatever a client sends is read and discarded.
        a.socket.write("anything at all\r\n");
        b.socket.write(QByteArray(5000, 'x'));
        QTRY_COMPARE_WITH_TIMEOUT(a.received, sent, 3000);
        QTRY_COMPARE_WITH_TIMEOUT(b.received, sent, 3000);
        QTRY_COMPARE_WITH_TIMEOUT(server.bytesIgnored(), quint64(17 + 5000), 3000);
        const QList<ClientInfo> list = server.clients();
        QCOMPARE(list.size(), 2);
        for (const ClientInfo &c : list) {
            QCOMPARE(c.address.toString(), QStringLiteral("127.0.0.1"));
            QVERIFY(c.port == a.socket.localPort() || c.port == b.socket.localPort());
            QVERIFY(c.streaming);
            QVERIFY(c.user.isEmpty());
        }
        QTRY_COMPARE_WITH_TIMEOUT(server.clients().value(0).bytesSent, quint64(sent.size()), 3000);
    }

    void aClientThatGoesIsForgotten() {
        RawStreamServer server;
        QVERIFY(server.listen());
        QSignalSpy gone(&server, &RawStreamServer::clientDisconnected);
        auto a = std::make_unique<TestClient>(server.port());
        QTRY_COMPARE_WITH_TIMEOUT(server.clients().size(), 1, 3000);
        a.reset();
        QTRY_COMPARE_WITH_TIMEOUT(gone.size(), 1, 3000);
        QCOMPARE(server.clients().size(), 0);
        server.publish("after"); // nobody: nothing happens
    }

    void aClientThatDoesNotReadIsDropped() {
        RawStreamServer server;
        ServeLimits limits;
        limits.queueBytes = 32 * 1024;
        limits.socketSendBuffer = 8 * 1024;
        server.setLimits(limits);
        QVERIFY(server.listen());
        TestClient fast(server.port()), slow(server.port(), {}, false);
        QTRY_COMPARE_WITH_TIMEOUT(server.clients().size(), 2, 3000);
        quint64 countedForSlow = 0;
        connect(&server, &RawStreamServer::clientDisconnected, this,
                [&](const ClientInfo &c, const QString &) { countedForSlow = c.bytesSent; });
        slow.socket.setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4096);
        QByteArray block(16 * 1024, 'r');
        QCryptographicHash sent(QCryptographicHash::Sha256);
        qint64 total = 0;
        for (int i = 0; i < 8000 && server.droppedSlow() == 0; ++i) {
            block[0] = char(i);
            server.publish(block);
            sent.addData(block);
            total += block.size();
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        }
        QCOMPARE(server.droppedSlow(), 1u);
        // What it is said to have been sent is what it reads then (the last flush counted).
        slow.reading = true;
        slow.socket.setReadBufferSize(0);
        slow.received += slow.socket.readAll();
        QTRY_VERIFY_WITH_TIMEOUT(slow.closed, 10000);
        slow.received += slow.socket.readAll();
        QCOMPARE(quint64(slow.received.size()), countedForSlow);
        QTRY_COMPARE_WITH_TIMEOUT(fast.received.size(), total, 10000);
        QCOMPARE(QCryptographicHash::hash(fast.received, QCryptographicHash::Sha256),
                 sent.result());
        QCOMPARE(server.clients().size(), 1);
    }

    // Beyond the client limit a connection is closed at once, and said.
    void aClientBeyondTheLimitIsTurnedAway() {
        RawStreamServer server;
        ServeLimits limits;
        limits.maxClients = 2;
        server.setLimits(limits);
        QVERIFY(server.listen());
        QList<ClientInfo> away;
        connect(&server, &RawStreamServer::clientTurnedAway, this,
                [&](const ClientInfo &c) { away << c; });
        TestClient a(server.port()), b(server.port());
        QTRY_COMPARE_WITH_TIMEOUT(server.clients().size(), 2, 3000);
        TestClient c(server.port());
        QTRY_COMPARE_WITH_TIMEOUT(away.size(), 1, 3000);
        QVERIFY(away[0].address.isLoopback());
        QCOMPARE(server.overCapacity(), 1u);
        QCOMPARE(server.clients().size(), 2);
    }

    // A client the user drops is closed and said so; the other goes on being served.
    void aClientTheUserDropsIsClosedAndTheOtherStays() {
        RawStreamServer server;
        QVERIFY(server.listen());
        QList<QPair<ClientInfo, QString>> gone;
        connect(&server, &RawStreamServer::clientDisconnected, this,
                [&](const ClientInfo &c, const QString &why) {
                    gone.append({c, why});
                });
        TestClient a(server.port()), b(server.port());
        QTRY_COMPARE_WITH_TIMEOUT(server.clients().size(), 2, 3000);
        const auto byPort = [&](quint16 port) {
            for (const ClientInfo &c : server.clients())
                if (c.port == port) return c.id;
            return quint64(0);
        };
        const quint64 idA = byPort(a.socket.localPort());
        QVERIFY(idA != 0);
        server.publish("before\r\n");
        QTRY_COMPARE_WITH_TIMEOUT(a.received, QByteArray("before\r\n"), 3000);
        QVERIFY(server.dropClient(idA));
        QCOMPARE(gone.size(), 1);
        QCOMPARE(gone[0].first.id, idA);
        QCOMPARE(gone[0].second, QStringLiteral("dropped by the user"));
        QVERIFY(!server.dropClient(idA)); // gone already
        QVERIFY(!server.dropClient(999));
        QTRY_VERIFY_WITH_TIMEOUT(a.closed, 3000);
        server.publish("after\r\n");
        QTRY_COMPARE_WITH_TIMEOUT(b.received, QByteArray("before\r\nafter\r\n"), 3000);
        QCOMPARE(a.received, QByteArray("before\r\n"));
        QCOMPARE(server.clients().size(), 1);
    }
};

QTEST_GUILESS_MAIN(TstRawStreamServer)
#include "tst_raw_stream_server.moc"
