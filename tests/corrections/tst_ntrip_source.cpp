// NtripSource against a caster written in the test (QTcpServer on 127.0.0.1): NTRIP 1 and 2
// data byte-exact (chunks cut inside RTCM frames), every refusal said in words that name the
// revision that answered and never the credentials, drops and stalls retried with growing
// waits, the GGA upload, the source table, corrupt frames counted by the monitor.
#include "corrections/corrections_monitor.h"
#include "corrections/ntrip_source.h"
#include "rtcm_fixtures.h"
#include "source_watch.h"
#include "test_caster.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::corrections;
using namespace corrections_test;
using State = CorrectionSource::State;

namespace {

NtripSettings settingsFor(const TstCaster &caster, int version) {
    NtripSettings s;
    s.host = QStringLiteral("127.0.0.1");
    s.port = caster.port();
    s.mountpoint = QString::fromLatin1(caster.mountpoint);
    s.user = QString::fromLatin1(caster.user);
    s.password = QString::fromLatin1(caster.password);
    s.version = ntrip::NtripVersion(version);
    return s;
}

// Quick retries for tests: 100 ms doubling to 400 ms.
void quickRetries(CorrectionSource &s) {
    s.setReconnectSettings({100, 400, 60000});
}

bool ggaChecksumsAreRight(const QByteArray &uploads, int &count) {
    count = 0;
    for (const QByteArray &line : uploads.split('\n')) {
        const QByteArray l = line.trimmed();
        if (l.isEmpty()) continue;
        if (!l.startsWith("$GPGGA,")) return false;
        const int star = l.indexOf('*');
        if (star < 0) return false;
        quint8 x = 0;
        for (int i = 1; i < star; ++i) x ^= quint8(l[i]);
        if (l.mid(star + 1) != QByteArray::number(x, 16).rightJustified(2, '0').toUpper())
            return false;
        ++count;
    }
    return true;
}

} // namespace

class TstNtripSource : public QObject {
    Q_OBJECT
private slots:
    void goodDataArrivesByteExact_data() {
        QTest::addColumn<int>("version");
        QTest::addColumn<bool>("v1Only");
        QTest::addColumn<QString>("requestLine");
        QTest::addColumn<QString>("status");
        QTest::newRow("NTRIP 2, chunked") << 2 << false << "GET /MOUNT HTTP/1.1"
                                          << "(NTRIP 2 (HTTP/1.1), chunked)";
        QTest::newRow("NTRIP 1, ICY") << 1 << false << "GET /MOUNT HTTP/1.0"
                                      << "(NTRIP 1 (ICY))";
        QTest::newRow("NTRIP 2 asked, an NTRIP 1 caster answers")
                << 2 << true << "GET /MOUNT HTTP/1.1"
                << "asked NTRIP 2, the caster answered NTRIP 1 (ICY)";
    }
    void goodDataArrivesByteExact() {
        QFETCH(int, version);
        QFETCH(bool, v1Only);
        QFETCH(QString, requestLine);
        QFETCH(QString, status);
        TstCaster caster;
        caster.v1Only = v1Only;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, version));
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QVERIFY2(source.statusText().contains(status), qPrintable(source.statusText()));
        QVERIFY(caster.requests.value(0).startsWith(requestLine.toLatin1()));
        QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 2000);

        QByteArray sent;
        for (const QByteArray &epoch : baseEpochs(5)) {
            caster.send(epoch);
            sent += epoch;
            QTest::qWait(20);
        }
        QTRY_COMPARE_WITH_TIMEOUT(watch.data.size(), sent.size(), 5000);
        QCOMPARE(watch.data, sent);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(0));
        QCOMPARE(watch.monitor.bytesSkipped(), std::uint64_t(0));
        QCOMPARE(watch.monitor.messageType(1074, 0)->count, std::uint64_t(5));
        QCOMPARE(watch.monitor.messageType(1084, 0)->count, std::uint64_t(5));
        QVERIFY(watch.errors.isEmpty());
        QCOMPARE(source.bytesReceived(), quint64(sent.size()));
    }

    void wrongCredentialsAreSaidInWords_data() {
        QTest::addColumn<int>("version");
        QTest::addColumn<QString>("revision");
        QTest::newRow("NTRIP 1: a bare HTTP/1.0 401 line")
                << 1 << "(401 Unauthorized, HTTP/1.0 reply)";
        QTest::newRow("NTRIP 2: a whole 401 head")
                << 2 << "(401 Unauthorized, NTRIP 2 (HTTP/1.1) reply)";
    }
    void wrongCredentialsAreSaidInWords() {
        QFETCH(int, version);
        QFETCH(QString, revision);
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSettings s = settingsFor(caster, version);
        s.password = QStringLiteral("wrong-pw-123");
        NtripSource source(s);
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Failed, 5000);
        QCOMPARE(watch.errors.size(), 1);
        const QString e = watch.errors.first();
        QVERIFY2(e.contains("refused the user name or password for mountpoint MOUNT"),
                 qPrintable(e));
        QVERIFY2(e.contains(revision), qPrintable(e));
        QTest::qWait(300); // a wrong password is not retried
        QCOMPARE(caster.connections, 1);
        QVERIFY(!watch.said("wrong-pw-123"));
        QVERIFY(!watch.said("rover7"));
    }

    void anUnknownMountpointIsSaidInWords_data() {
        QTest::addColumn<int>("version");
        QTest::addColumn<QString>("revision");
        QTest::newRow("NTRIP 1: SOURCETABLE 200 OK") << 1 << "(NTRIP 1 (SOURCETABLE) reply)";
        QTest::newRow("NTRIP 2: gnss/sourcetable") << 2 << "(NTRIP 2 (HTTP/1.1) reply)";
    }
    void anUnknownMountpointIsSaidInWords() {
        QFETCH(int, version);
        QFETCH(QString, revision);
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSettings s = settingsFor(caster, version);
        s.mountpoint = QStringLiteral("NOSUCH");
        NtripSource source(s);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Failed, 5000);
        const QString e = watch.errors.value(0);
        QVERIFY2(e.contains("Mountpoint NOSUCH is not on 127.0.0.1:"), qPrintable(e));
        QVERIFY2(e.contains("sent its source table instead of data"), qPrintable(e));
        QVERIFY2(e.contains(revision), qPrintable(e));
        QCOMPARE(source.statusText(), e);
        QVERIFY(source.failedOnRequest()); // the request's fault, not the caster's
    }

    void aDroppedStreamIsRetriedWithGrowingWaitsUntilTheCasterIsBack() {
        TstCaster caster;
        QVERIFY(caster.listen());
        const quint16 port = caster.port();
        NtripSource source(settingsFor(caster, 2));
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 5000);
        const QList<QByteArray> epochs = baseEpochs(4);
        caster.send(epochs[0]);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epochs[0], 3000);

        caster.close(); // the caster goes away mid-stream...
        caster.dropClients();
        QTRY_VERIFY_WITH_TIMEOUT(watch.errors.size() >= 4, 5000);
        QVERIFY2(watch.errors[0].contains("closed the connection mid-stream"),
                 qPrintable(watch.errors[0]));
        QVERIFY2(watch.errors[1].contains("refused the connection"), qPrintable(watch.errors[1]));
        QList<int> waits;
        for (int w : watch.waits.mid(0, 4)) waits.append((w + 50) / 100 * 100);
        QCOMPARE(waits, (QList<int>{100, 200, 400, 400}));

        QVERIFY(caster.listen(port)); // ...and comes back
        QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 5000);
        QCOMPARE(source.state(), State::Receiving);
        caster.send(epochs[1]);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epochs[0] + epochs[1], 3000);
    }

    void aMinuteOfDataMakesTheNextWaitShortAgain() {
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 1));
        quickRetries(source);
        qint64 fakeNow = 0;
        source.setClock([&fakeNow] { return fakeNow; });
        SourceWatch watch(source);
        source.start();
        const QByteArray epoch = baseEpochs(1).first();
        for (int round = 0; round < 3; ++round) {
            QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 5000);
            caster.send(epoch);
            QTRY_COMPARE_WITH_TIMEOUT(watch.data.size(), epoch.size() * (2 * round + 1), 3000);
            // Round 1 lasts a (fake) minute: healthy. The others a second.
            fakeNow += round == 1 ? 61000 : 1000;
            caster.send(epoch);
            QTRY_COMPARE_WITH_TIMEOUT(watch.data.size(), epoch.size() * (2 * round + 2), 3000);
            caster.dropClients();
            QTRY_COMPARE_WITH_TIMEOUT(watch.waits.size(), round + 1, 3000);
        }
        QList<int> waits;
        for (int w : watch.waits) waits.append((w + 50) / 100 * 100);
        QCOMPARE(waits, (QList<int>{100, 100, 200}));
    }

    void aStalledStreamIsDroppedAndRetried() {
        TstCaster caster;
        caster.silent = true;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 2));
        quickRetries(source);
        source.setStallTimeout(300);
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(!watch.errors.isEmpty(), 3000);
        QVERIFY2(watch.errors[0].contains("No data from 127.0.0.1:") &&
                         watch.errors[0].contains("/MOUNT for 0.3 s"),
                 qPrintable(watch.errors[0]));
        QVERIFY(watch.states.contains(State::Receiving));
        QTRY_VERIFY_WITH_TIMEOUT(caster.connections >= 2, 3000); // tried again
    }

    void aRefusedPortIsRetried() {
        NtripSettings s;
        s.host = QStringLiteral("127.0.0.1");
        s.port = closedPort();
        s.mountpoint = QStringLiteral("MOUNT");
        NtripSource source(s);
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::WaitingToRetry, 5000);
        QVERIFY2(watch.errors.value(0).contains(
                         QString("127.0.0.1:%1 refused the connection").arg(s.port)),
                 qPrintable(watch.errors.value(0)));
        QVERIFY2(source.statusText().contains("trying again in 1 s"),
                 qPrintable(source.statusText()));
        QVERIFY(source.retryInMs() > 0);
        source.stop();
        QCOMPARE(source.state(), State::Idle);
        QCOMPARE(source.retryInMs(), 0);
    }

    void ggaGoesUpAtTheStartAndThenRegularly_data() {
        QTest::addColumn<int>("version");
        QTest::addColumn<int>("policy");
        QTest::addColumn<bool>("tableSaysWanted");
        QTest::addColumn<bool>("sent");
        using G = NtripSettings::Gga;
        QTest::newRow("NTRIP 1, wanted") << 1 << int(G::Auto) << true << true;
        QTest::newRow("NTRIP 2, wanted") << 2 << int(G::Auto) << true << true;
        QTest::newRow("not wanted by the table") << 2 << int(G::Auto) << false << false;
        QTest::newRow("always, whatever the table") << 1 << int(G::Always) << false << true;
        QTest::newRow("never") << 2 << int(G::Never) << true << false;
    }
    void ggaGoesUpAtTheStartAndThenRegularly() {
        QFETCH(int, version);
        QFETCH(int, policy);
        QFETCH(bool, tableSaysWanted);
        QFETCH(bool, sent);
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSettings s = settingsFor(caster, version);
        s.gga = NtripSettings::Gga(policy);
        s.ggaIntervalMs = 200;
        NtripSource source(s);
        source.setMountpointWantsGga(tableSaysWanted);
        source.setRoverPosition(roverPosition());
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        if (sent) QTRY_VERIFY_WITH_TIMEOUT(caster.uploads.startsWith("$GPGGA,"), 150); // at once
        QTest::qWait(700);
        int count = 0;
        QVERIFY2(ggaChecksumsAreRight(caster.uploads, count), caster.uploads.constData());
        if (sent) {
            QVERIFY2(count >= 3 && count <= 6, qPrintable(QString::number(count)));
            QVERIFY(caster.uploads.contains(",5545.07200,N,03737.10400,E,"));
        } else {
            QCOMPARE(count, 0);
        }
    }

    void aPositionArrivingLateIsSentAtOnce() {
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSettings s = settingsFor(caster, 2);
        s.ggaIntervalMs = 60000;
        NtripSource source(s);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QTest::qWait(100);
        QVERIFY(caster.uploads.isEmpty());
        ntrip::GgaPosition p;
        p.latDeg = 1;
        p.lonDeg = 2;
        source.setRoverPosition(p); // the receiver's first fix
        QTRY_VERIFY_WITH_TIMEOUT(caster.uploads.startsWith("$GPGGA,"), 1000);
    }

    void malformedChunksAreReportedAndRetried() {
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 2));
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 5000);
        caster.sendRaw("5\r\nab");
        caster.sendRaw("cde\r\nzz\r\n");
        QTRY_VERIFY_WITH_TIMEOUT(!watch.errors.isEmpty(), 3000);
        QVERIFY2(watch.errors[0].contains("sent malformed chunked data: chunk size is not "
                                          "hexadecimal (got 'z')"),
                 qPrintable(watch.errors[0]));
        QCOMPARE(watch.data, QByteArray("abcde")); // what came before the fault
        QTRY_VERIFY_WITH_TIMEOUT(caster.connections >= 2, 3000);
    }

    void corruptFramesAreCountedByTheMonitor() {
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 2));
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(caster.streamingClients(), 1, 5000);
        const QList<QByteArray> epochs = baseEpochs(3);
        QByteArray corrupt = epochs[1];
        corrupt[10] = char(corrupt[10] ^ 0x55); // inside the first frame's payload (1074)
        caster.send(epochs[0] + corrupt + epochs[2]);
        QTRY_VERIFY_WITH_TIMEOUT(
                watch.monitor.bytesTotal() ==
                        std::uint64_t(epochs[0].size() + corrupt.size() + epochs[2].size()),
                3000);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(1));
        QCOMPARE(watch.monitor.messageType(1074, 0)->count, std::uint64_t(2));
        QCOMPARE(watch.monitor.messageType(1084, 0)->count, std::uint64_t(3));
        QVERIFY(watch.monitor.bytesSkipped() > 0);
    }

    void theSourceTableIsFetchedAndParsed_data() {
        QTest::addColumn<int>("version");
        QTest::newRow("NTRIP 1") << 1;
        QTest::newRow("NTRIP 2") << 2;
    }
    void theSourceTableIsFetchedAndParsed() {
        QFETCH(int, version);
        TstCaster caster;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, version));
        QSignalSpy got(&source, &NtripSource::sourceTableReceived);
        source.fetchSourceTable();
        QVERIFY(got.wait(5000));
        const auto table = got.first().first().value<ntrip::SourceTable>();
        QVERIFY(table.complete);
        QCOMPARE(int(table.streams.size()), 3);
        QCOMPARE(int(table.casters.size()), 1);
        QCOMPARE(int(table.networks.size()), 1);
        QVERIFY(table.find("MOUNT") && table.find("MOUNT")->wantsGga);
        QVERIFY(caster.requests.value(0).startsWith("GET / HTTP/1."));
        QCOMPARE(source.state(), State::Idle); // the stream itself was not touched
    }

    void aSourceTableFromNoCasterIsRefusedInWords() {
        TstCaster caster;
        caster.rawReply = "HTTP/1.1 200 OK\r\nContent-Type: text/html\r\n\r\n<html></html>";
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 2));
        QSignalSpy failed(&source, &NtripSource::sourceTableFailed);
        source.fetchSourceTable();
        QVERIFY(failed.wait(5000));
        QVERIFY2(failed.first().first().toString().contains("answered with text/html"),
                 qPrintable(failed.first().first().toString()));
    }

    void repliesThatAreNoNtripAreToldApart_data() {
        QTest::addColumn<QByteArray>("reply");
        QTest::addColumn<QString>("words");
        QTest::addColumn<State>("state");
        QTest::newRow("another protocol")
                << QByteArray("SSH-2.0-OpenSSH_9.2\r\n")
                << "did not answer like an NTRIP caster (it sent \"SS\")" << State::Failed;
        QTest::newRow("a raw RTCM port") << QByteArray("\xd3\x00\x13>\xd0\x00\x03", 7)
                                         << "needs a TCP source instead" << State::Failed;
        QTest::newRow("a web page") << QByteArray("HTTP/1.1 200 OK\r\nContent-Type: "
                                                  "text/html\r\n\r\n<html/>")
                                    << "answered with text/html, not GNSS data" << State::Failed;
        QTest::newRow("a caster too busy: retried")
                << QByteArray("HTTP/1.1 503 Service Unavailable\r\n\r\n")
                << "answered \"HTTP/1.1 503 Service Unavailable\" for mountpoint MOUNT"
                << State::WaitingToRetry;
        QTest::newRow("an old caster's ERROR line")
                << QByteArray("ERROR - Bad Password\r\n")
                << "answered \"ERROR - Bad Password\" for mountpoint MOUNT (NTRIP 1 (ERROR line))"
                << State::Failed;
        QTest::newRow("nothing at all")
                << QByteArray(" ") << "did not answer like" << State::Failed;
    }
    void repliesThatAreNoNtripAreToldApart() {
        QFETCH(QByteArray, reply);
        QFETCH(QString, words);
        QFETCH(State, state);
        TstCaster caster;
        caster.rawReply = reply;
        QVERIFY(caster.listen());
        NtripSource source(settingsFor(caster, 2));
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(!watch.errors.isEmpty(), 5000);
        QVERIFY2(watch.errors[0].contains(words), qPrintable(watch.errors[0]));
        QCOMPARE(source.state(), state);
    }

    void aClosedConnectionWithoutAnswerIsRetried() {
        QTcpServer server; // accepts, then hangs up without a word
        QVERIFY(server.listen(QHostAddress::LocalHost));
        connect(&server, &QTcpServer::newConnection, [&] {
            while (QTcpSocket *s = server.nextPendingConnection()) {
                connect(s, &QTcpSocket::readyRead, s, [s] {
                    s->readAll();
                    s->disconnectFromHost();
                });
            }
        });
        NtripSettings s;
        s.host = QStringLiteral("127.0.0.1");
        s.port = server.serverPort();
        s.mountpoint = QStringLiteral("M");
        NtripSource source(s);
        quickRetries(source);
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(!watch.errors.isEmpty(), 5000);
        QVERIFY2(watch.errors[0].contains("closed the connection without answering"),
                 qPrintable(watch.errors[0]));
        QCOMPARE(source.state(), State::WaitingToRetry);
    }

    void socketFailuresAreSaidInWords_data() {
        QTest::addColumn<int>("error");
        QTest::addColumn<QString>("words");
        QTest::newRow("host not found")
                << int(QAbstractSocket::HostNotFoundError)
                << "Host caster.example not found: check the name and the network";
        QTest::newRow("refused") << int(QAbstractSocket::ConnectionRefusedError)
                                 << "caster.example:2101 refused the connection";
        QTest::newRow("timeout") << int(QAbstractSocket::SocketTimeoutError)
                                 << "caster.example:2101 did not answer in time";
        QTest::newRow("anything else") << int(QAbstractSocket::SslHandshakeFailedError)
                                       << "Connection to caster.example:2101 failed: Qt says";
    }
    void socketFailuresAreSaidInWords() {
        QFETCH(int, error);
        QFETCH(QString, words);
        const QString text = CorrectionSource::describeSocketError(
                QAbstractSocket::SocketError(error), "caster.example:2101", "caster.example",
                "Qt says");
        QVERIFY2(text.startsWith(words), qPrintable(text));
    }

    void noMountpointIsSaidBeforeConnecting() {
        NtripSettings s;
        s.host = QStringLiteral("127.0.0.1");
        s.port = closedPort();
        NtripSource source(s);
        SourceWatch watch(source);
        source.start();
        QCOMPARE(source.state(), State::Failed);
        QVERIFY2(watch.errors.value(0).contains("No mountpoint given"),
                 qPrintable(watch.errors.value(0)));
    }
};

QTEST_GUILESS_MAIN(TstNtripSource)
#include "tst_ntrip_source.moc"
