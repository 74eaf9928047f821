// NtripCaster on 127.0.0.1:0 with QTcpSocket clients: NTRIP 1 and 2 streams byte-exact (only
// whole RTCM frames, NTRIP 2 chunked), the refusals (unknown mountpoint before credentials,
// 401, 400, 405, the table without a password), a client that does not read dropped while
// another gets every byte, the head timeout, the client list and the last chunk at close.
#include "serve/ntrip_caster.h"
#include "serve_test_client.h"

#include <QCryptographicHash>
#include <QSignalSpy>

using namespace gnss::serve;
using namespace serve_test;

namespace {

// The caster of most tests: BASE (password) and OPEN (none), user "u" with password "pw".
std::unique_ptr<NtripCaster> makeCaster(const ServeLimits &limits = {}) {
    auto c = std::make_unique<NtripCaster>();
    c->setLimits(limits);
    c->addMount({QStringLiteral("BASE"), true, {}});
    c->addMount({QStringLiteral("OPEN"), false, {}});
    c->addUser(QStringLiteral("u"), QStringLiteral("pw"));
    if (!c->listen()) return nullptr;
    return c;
}

// Epochs of the simulated base with NMEA between them: what a receiver's port carries.
struct Published {
    QList<QByteArray> withNmea; // as published
    QByteArray frames;          // what clients must get
};
Published publishedEpochs(int count) {
    Published p;
    for (const QByteArray &epoch : corrections_test::baseEpochs(count)) {
        p.withNmea << "$GPGGA,120000.00,5545.0,N,03737.0,E,1,08,1.0,150.0,M,14.0,M,,*00\r\n" +
                              epoch;
        p.frames += epoch;
    }
    return p;
}

} // namespace

class TstNtripCaster : public QObject {
    Q_OBJECT
private slots:
    void streamsAreByteExact_data() {
        QTest::addColumn<int>("version");
        QTest::newRow("NTRIP 1") << 1;
        QTest::newRow("NTRIP 2") << 2;
    }
    void streamsAreByteExact() {
        QFETCH(int, version);
        auto caster = makeCaster();
        QVERIFY(caster);
        QCOMPARE(caster->address().toString(), QStringLiteral("127.0.0.1"));
        TestClient c(caster->port(),
                     version == 1 ? v1Request("BASE", "u:pw") : v2Request("BASE", "u:pw"));
        QTRY_VERIFY_WITH_TIMEOUT(c.received.contains("\r\n\r\n"), 3000);
        QCOMPARE(c.statusLine(),
                 version == 1 ? QByteArray("ICY 200 OK") : QByteArray("HTTP/1.1 200 OK"));
        if (version == 2) {
            QVERIFY(c.received.contains("Ntrip-Version: Ntrip/2.0\r\n"));
            QVERIFY(c.received.contains("Content-Type: gnss/data\r\n"));
            QVERIFY(c.received.contains("Transfer-Encoding: chunked\r\n"));
        }
        const Published p = publishedEpochs(5);
        for (const QByteArray &b : p.withNmea) {
            // Cut anywhere: frames across publishes still arrive whole.
            caster->publish("BASE", b.left(17));
            caster->publish("BASE", b.mid(17));
        }
        auto data = [&] { return version == 1 ? c.body() : unchunked(c.body()); };
        QTRY_COMPARE_WITH_TIMEOUT(data().size(), p.frames.size(), 3000);
        QCOMPARE(data(), p.frames);
        QVERIFY(caster->bytesNotRtcm("BASE") >= 5 * 60);
        // The table now says what was served.
        const QByteArray table = caster->sourceTable();
        QVERIFY2(table.startsWith("STR;BASE;BASE;RTCM 3.3;"), table.constData());
        QVERIFY2(table.contains(";GPS+GLO;"), table.constData());
        QVERIFY2(table.contains(";55.75;37.62;0;0;GNSS Workbench;none;B;N;"), table.constData());
        QVERIFY(table.contains("STR;OPEN;OPEN;RTCM 3.3;;0;;LOCAL;XXX;0.00;0.00;0;0;"));
    }

    void refusals_data() {
        QTest::addColumn<QByteArray>("request");
        QTest::addColumn<QByteArray>("status");
        QTest::addColumn<QByteArray>("contains");
        QTest::newRow("unknown mount, NTRIP 1, wrong password: the table")
                << v1Request("NOPE", "u:wrong") << QByteArray("SOURCETABLE 200 OK")
                << QByteArray("ENDSOURCETABLE\r\n");
        QTest::newRow("unknown mount, NTRIP 2, wrong password: 404")
                << v2Request("NOPE", "u:wrong") << QByteArray("HTTP/1.1 404 Not Found")
                << QByteArray("Ntrip-Version: Ntrip/2.0");
        QTest::newRow("wrong password, NTRIP 1")
                << v1Request("BASE", "u:wrong") << QByteArray("HTTP/1.0 401 Unauthorized")
                << QByteArray("WWW-Authenticate: Basic realm=\"");
        QTest::newRow("wrong user, NTRIP 2")
                << v2Request("BASE", "x:pw") << QByteArray("HTTP/1.1 401 Unauthorized")
                << QByteArray("WWW-Authenticate: Basic realm=\"");
        QTest::newRow("no password") << v1Request("BASE") << QByteArray("HTTP/1.0 401 Unauthorized")
                                     << QByteArray("WWW-Authenticate: Basic");
        QTest::newRow("malformed") << QByteArray("GET /BASE\r\n\r\n")
                                   << QByteArray("HTTP/1.0 400 Bad Request") << QByteArray();
        QTest::newRow("bad Base64")
                << QByteArray("GET /BASE HTTP/1.0\r\nAuthorization: Basic ***\r\n\r\n")
                << QByteArray("HTTP/1.0 400 Bad Request") << QByteArray();
        QTest::newRow("POST") << QByteArray("POST /BASE HTTP/1.1\r\n\r\n")
                              << QByteArray("HTTP/1.0 405 Method Not Allowed")
                              << QByteArray("Allow: GET");
        QTest::newRow("the table, NTRIP 1, no password")
                << v1Request("") << QByteArray("SOURCETABLE 200 OK") << QByteArray("STR;BASE;");
        QTest::newRow("the table, NTRIP 2, no password")
                << v2Request("") << QByteArray("HTTP/1.1 200 OK")
                << QByteArray("Content-Type: gnss/sourcetable");
    }
    void refusals() {
        QFETCH(QByteArray, request);
        QFETCH(QByteArray, status);
        QFETCH(QByteArray, contains);
        auto caster = makeCaster();
        QVERIFY(caster);
        TestClient c(caster->port(), request);
        QTRY_VERIFY_WITH_TIMEOUT(c.closed, 3000); // answered, then closed by the caster
        QCOMPARE(c.statusLine(), status);
        QVERIFY2(c.received.contains(contains), c.received.constData());
        QVERIFY(!c.received.contains("pw"));
        QTRY_COMPARE_WITH_TIMEOUT(caster->clients().size(), 0, 3000);
        QCOMPARE(caster->counters().streams, 0u);
    }

    void theTableListsEveryMount() {
        auto caster = makeCaster();
        QVERIFY(caster);
        TestClient c(caster->port(), v1Request("", {}));
        QTRY_VERIFY_WITH_TIMEOUT(c.closed, 3000);
        const gnss::ntrip::SourceTable t = gnss::ntrip::parseSourceTable(c.body().toStdString());
        QVERIFY(t.complete);
        QCOMPARE(t.streams.size(), std::size_t(2));
        QCOMPARE(t.find("BASE")->authentication, std::string("B"));
        QCOMPARE(t.find("OPEN")->authentication, std::string("N"));
        QCOMPARE(c.received.indexOf("Content-Length: " + QByteArray::number(c.body().size())) > 0,
                 true);
    }

    void anOpenMountNeedsNoPassword() {
        auto caster = makeCaster();
        QVERIFY(caster);
        TestClient c(caster->port(), v1Request("OPEN"));
        QTRY_COMPARE_WITH_TIMEOUT(c.statusLine(), QByteArray("ICY 200 OK"), 3000);
        const Published p = publishedEpochs(2);
        for (const QByteArray &b : p.withNmea) caster->publish("OPEN", b);
        caster->publish("BASE", p.frames); // another mount's bytes do not arrive here
        QTRY_COMPARE_WITH_TIMEOUT(c.body(), p.frames, 3000);
        // Bytes the client sends (a GGA) are read and ignored.
        c.socket.write("$GPGGA,120000,5545.0,N,03737.0,E,1,08,1.0,150,M,14,M,,*00\r\n");
        QTest::qWait(100);
        QCOMPARE(caster->clients().size(), 1);
    }

    void aClientThatDoesNotReadIsDropped() {
        ServeLimits limits;
        limits.queueBytes = 64 * 1024;
        limits.socketSendBuffer = 8 * 1024;
        auto caster = makeCaster(limits);
        QVERIFY(caster);
        QSignalSpy gone(caster.get(), &NtripCaster::clientDisconnected);
        TestClient fast(caster->port(), v1Request("BASE", "u:pw"));
        TestClient slow(caster->port(), v1Request("BASE", "u:pw"), false);
        QTRY_COMPARE_WITH_TIMEOUT(caster->clients().size(), 2, 3000);
        QTRY_VERIFY_WITH_TIMEOUT(fast.received.startsWith("ICY 200 OK\r\n\r\n"), 3000);
        slow.socket.setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4096);
        // About 16 KiB of whole frames a publish.
        QByteArray block;
        for (const QByteArray &e : corrections_test::baseEpochs(200)) {
            if (block.size() > 16 * 1024) break;
            block += e;
        }
        QCryptographicHash sent(QCryptographicHash::Sha256);
        qint64 total = 0;
        for (int i = 0; i < 8000 && caster->counters().droppedSlow == 0; ++i) {
            caster->publish("BASE", block);
            sent.addData(block);
            total += block.size();
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        }
        QCOMPARE(caster->counters().droppedSlow, 1u);
        QVERIFY(total < 200ll * 1024 * 1024);
        QCOMPARE(gone.size(), 1);
        QVERIFY2(gone[0][1].toString().startsWith("dropped: it did not read"),
                 qPrintable(gone[0][1].toString()));
        // A few more after the drop: the reader keeps getting everything.
        for (int i = 0; i < 5; ++i) {
            caster->publish("BASE", block);
            sent.addData(block);
            total += block.size();
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        }
        QTRY_COMPARE_WITH_TIMEOUT(fast.body().size(), total, 10000);
        QCOMPARE(QCryptographicHash::hash(fast.body(), QCryptographicHash::Sha256), sent.result());
        QCOMPARE(caster->clients().size(), 1);
    }

    void aHeadThatNeverEndsIsDropped() {
        ServeLimits limits;
        limits.headTimeoutMs = 300;
        auto caster = makeCaster(limits);
        QVERIFY(caster);
        TestClient c(caster->port(), "GET /BASE HTTP/1.0\r\nUser-Agent: NTRIP");
        QTRY_VERIFY_WITH_TIMEOUT(c.closed, 3000);
        QCOMPARE(caster->counters().headTimeouts, 1u);
        QVERIFY(c.received.isEmpty());
    }

    void theClientListFollowsClients() {
        auto caster = makeCaster();
        QVERIFY(caster);
        QSignalSpy came(caster.get(), &NtripCaster::clientConnected);
        QSignalSpy started(caster.get(), &NtripCaster::streamStarted);
        QSignalSpy gone(caster.get(), &NtripCaster::clientDisconnected);
        auto c = std::make_unique<TestClient>(caster->port(), v2Request("BASE", "u:pw"));
        QTRY_COMPARE_WITH_TIMEOUT(started.size(), 1, 3000);
        QCOMPARE(came.size(), 1);
        const ClientInfo info = caster->clients().value(0);
        QCOMPARE(info.address.toString(), QStringLiteral("127.0.0.1"));
        QCOMPARE(info.port, c->socket.localPort());
        QCOMPARE(info.user, QStringLiteral("u"));
        QCOMPARE(info.mountpoint, QStringLiteral("BASE"));
        QVERIFY(info.streaming);
        QVERIFY(info.since.secsTo(QDateTime::currentDateTimeUtc()) < 5);
        caster->publish("BASE", publishedEpochs(1).frames);
        QTRY_VERIFY_WITH_TIMEOUT(caster->clients().value(0).bytesSent > 200, 3000);
        c.reset();
        QTRY_COMPARE_WITH_TIMEOUT(gone.size(), 1, 3000);
        QCOMPARE(gone[0][1].toString(), QStringLiteral("closed by the client"));
        QCOMPARE(caster->clients().size(), 0);
    }

    void closingEndsNtrip2StreamsWithTheLastChunk() {
        auto caster = makeCaster();
        QVERIFY(caster);
        TestClient c(caster->port(), v2Request("BASE", "u:pw"));
        QTRY_COMPARE_WITH_TIMEOUT(caster->clients().value(0).streaming, true, 3000);
        caster->publish("BASE", publishedEpochs(1).frames);
        caster->close();
        QTRY_VERIFY_WITH_TIMEOUT(c.closed, 3000);
        bool finished = false;
        QCOMPARE(unchunked(c.body(), &finished), publishedEpochs(1).frames);
        QVERIFY(finished);
    }
};

QTEST_GUILESS_MAIN(TstNtripCaster)
#include "tst_ntrip_caster.moc"
