// GpsdTransport without gpsd: the HOST[:PORT][/DEVICE] forms, the source's URL, what the reader
// keeps of gpsd's output (the receiver's sentences) and what it strips (gpsd's JSON, hex dumps of
// binary packets), and the conversation with a scripted gpsd on 127.0.0.1 (greeting, watch
// request, devices, refusals, a server that is not gpsd, gpsd going away).
#include "builtin/dialects.h"
#include "builtin_registry.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "link/gpsd_reader.h"
#include "link/gpsd_transport.h"
#include "link/sentence_stream.h"
#include "link/source_spec.h"
#include "link/transport_factory.h"

#include <QJsonDocument>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

using namespace gnss;
using namespace gnss::link;

namespace {

const QByteArray kGga = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
const QByteArray kRmc = "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A\r\n";

// A scripted gpsd: greets each client with VERSION, answers ?WATCH with DEVICES and WATCH, then
// sends what the test gives it. `devices` is what it claims to have; `greeting` replaces the
// VERSION line (a server that is not gpsd).
class FakeGpsd : public QObject {
public:
    QStringList devices{"/dev/ttyUSB0", "/dev/ttyACM0"};
    QByteArray greeting = R"({"class":"VERSION","release":"3.22","rev":"3.22","proto_major":3,)"
                          R"("proto_minor":14})"
                          "\r\n";
    QByteArray request; // the last ?WATCH received
    QTcpSocket *client = nullptr;
    QTcpServer server;

    FakeGpsd() {
        server.listen(QHostAddress::LocalHost);
        connect(&server, &QTcpServer::newConnection, this, [this] {
            client = server.nextPendingConnection();
            client->write(greeting);
            connect(client, &QTcpSocket::readyRead, this, [this] {
                request += client->readAll();
                if (!request.endsWith('\n')) return;
                QByteArray reply = R"({"class":"DEVICES","devices":[)";
                for (int i = 0; i < devices.size(); ++i)
                    reply += QByteArray(i ? "," : "") + R"({"class":"DEVICE","path":")" +
                             devices[i].toUtf8() + R"(","driver":"NMEA0183","activated":"x"})";
                reply += "]}\r\n";
                reply += R"({"class":"WATCH","enable":true,"json":false,"raw":1})"
                         "\r\n";
                client->write(reply);
            });
        });
    }
    quint16 port() const { return server.serverPort(); }
    void send(const QByteArray &bytes) {
        client->write(bytes);
        client->flush();
    }
};

GpsdTransport::Target target(quint16 port, const QString &device = {}) {
    GpsdTransport::Target t;
    t.host = QStringLiteral("127.0.0.1");
    t.port = port;
    t.device = device;
    return t;
}

} // namespace

class TstGpsdTransport : public QObject {
    Q_OBJECT
private slots:
    void targetForms_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::addColumn<QString>("device");
        QTest::newRow("host") << "localhost"
                              << "localhost" << 2947 << "";
        QTest::newRow("host:port") << "10.0.0.2:2948"
                                   << "10.0.0.2" << 2948 << "";
        QTest::newRow("host/device") << "localhost/dev/ttyUSB0"
                                     << "localhost" << 2947 << "/dev/ttyUSB0";
        QTest::newRow("url") << "gpsd://gps.lan:3000/dev/ttyACM0"
                             << "gps.lan" << 3000 << "/dev/ttyACM0";
        QTest::newRow("device only") << "/dev/ttyACM0"
                                     << "127.0.0.1" << 2947 << "/dev/ttyACM0";
        QTest::newRow("port only") << ":2948"
                                   << "127.0.0.1" << 2948 << "";
        QTest::newRow("ipv6 with port") << "[::1]:2947/dev/gps0"
                                        << "::1" << 2947 << "/dev/gps0";
        QTest::newRow("bare ipv6") << "fe80::1"
                                   << "fe80::1" << 2947 << "";
    }
    void targetForms() {
        QFETCH(QString, text);
        GpsdTransport::Target t;
        QString error;
        QVERIFY2(GpsdTransport::parseTarget(text, t, &error), qPrintable(error));
        QTEST(t.host, "host");
        QTEST(int(t.port), "port");
        QTEST(t.device, "device");
    }

    void badTargetsAreRefusedInWords_data() {
        QTest::addColumn<QString>("text");
        QTest::newRow("empty") << "";
        QTest::newRow("port 0") << "localhost:0";
        QTest::newRow("port too big") << "localhost:70000";
        QTest::newRow("port not a number") << "localhost:gps";
        QTest::newRow("space") << "local host";
        QTest::newRow("unclosed ipv6") << "[::1:2947";
    }
    void badTargetsAreRefusedInWords() {
        QFETCH(QString, text);
        GpsdTransport::Target t;
        QString error;
        QVERIFY(!GpsdTransport::parseTarget(text, t, &error));
        QVERIFY(!error.isEmpty());
    }

    void sourceSpecKeepsTheUrlForm() {
        const SourceSpec s{SourceSpec::Kind::Gpsd, "localhost:2947/dev/ttyUSB0"};
        QCOMPARE(s.toString(), QString("gpsd://localhost:2947/dev/ttyUSB0"));
        const SourceSpec back = SourceSpec::fromString(s.toString());
        QCOMPARE(back.kind, SourceSpec::Kind::Gpsd);
        QCOMPARE(back.name, s.name);
        QVERIFY(back.displayName().contains("gpsd"));
        QCOMPARE(SourceSpec::fromString("gpsd:localhost").name, QString("localhost"));
        // The link's own factory makes it (the GUI and gnss-cli share it).
        TransportFactory f;
        QVERIFY(f.supports(SourceSpec::Kind::Gpsd));
        QString error;
        auto t = f.make(s, &error);
        QVERIFY2(t, qPrintable(error));
        QVERIFY(qobject_cast<GpsdTransport *>(t.get()));
        QVERIFY(!t->canWrite());
        QVERIFY(t->readOnlyReason().contains("gpsd owns the port"));
        QVERIFY(!f.make({SourceSpec::Kind::Gpsd, "localhost:99999"}, &error));
        QVERIFY(error.contains("99999"));
    }

    void watchRequestAsksForRawSentencesOnly() {
        const QByteArray all = GpsdTransport::watchRequest({});
        QVERIFY(all.startsWith("?WATCH={"));
        QVERIFY(all.endsWith("}\n"));
        const QJsonObject w = QJsonDocument::fromJson(all.mid(7)).object();
        QCOMPARE(w.value("enable").toBool(), true);
        QCOMPARE(w.value("raw").toInt(), 1);
        QCOMPARE(w.value("json").toBool(true), false);
        QVERIFY(!w.contains("device"));
        const QJsonObject one =
                QJsonDocument::fromJson(GpsdTransport::watchRequest("/dev/ttyUSB0").mid(7))
                        .object();
        QCOMPARE(one.value("device").toString(), QString("/dev/ttyUSB0"));
    }

    void readerKeepsSentencesAndStripsTheRest() {
        GpsdReader r;
        std::vector<QJsonObject> reports;
        const QByteArray in = R"({"class":"VERSION","release":"3.22"})"
                              "\r\n" +
                              kGga + "b5620107" + QByteArray(40, 'a') + "\r\n" // a hex dump
                              + R"({"class":"DEVICE","path":"/dev/x","activated":0})"
                                "\r\n" +
                              "!AIVDM,1,1,,A,13u?etPv2;0n:dDPwUM1U1Cb069D,0*24\n" + kRmc +
                              "{not json\r\n";
        QByteArray out;
        // Any chunking gives the same result.
        for (qsizetype i = 0; i < in.size(); i += 7) out += r.feed(in.mid(i, 7), reports);
        QCOMPARE(out, kGga + "!AIVDM,1,1,,A,13u?etPv2;0n:dDPwUM1U1Cb069D,0*24\r\n" + kRmc);
        QCOMPARE(int(reports.size()), 2);
        QCOMPARE(reports[0].value("class").toString(), QString("VERSION"));
        QCOMPARE(reports[1].value("class").toString(), QString("DEVICE"));
        QCOMPARE(r.linesDropped(), quint64(2)); // the hex dump and the broken JSON
    }

    void readerDropsALineWithoutEnd() {
        GpsdReader r;
        std::vector<QJsonObject> reports;
        QByteArray junk(GpsdReader::kMaxLine + 10, 'x');
        QVERIFY(r.feed(junk, reports).isEmpty());
        QVERIFY(r.feed(junk, reports).isEmpty());
        QCOMPARE(r.feed("tail\r\n" + kGga, reports), kGga); // the long line ends, the next counts
        QCOMPARE(r.linesDropped(), quint64(1));
    }

    void watchesAndDeliversOnlyTheReceiversSentences() {
        FakeGpsd gpsd;
        GpsdTransport t(target(gpsd.port(), "/dev/ttyACM0"));
        QSignalSpy received(&t, &Transport::bytesReceived);
        QVERIFY(t.open());
        QCOMPARE(t.state(), Transport::State::Connecting);
        QTRY_COMPARE(t.state(), Transport::State::Open);
        QCOMPARE(t.gpsdRelease(), QString("3.22"));
        QCOMPARE(t.gpsdDevices(), (QStringList{"/dev/ttyUSB0", "/dev/ttyACM0"}));
        const QJsonObject w = QJsonDocument::fromJson(gpsd.request.mid(7)).object();
        QCOMPARE(w.value("device").toString(), QString("/dev/ttyACM0"));
        QCOMPARE(w.value("raw").toInt(), 1);
        gpsd.send(kGga +
                  R"({"class":"DEVICE","path":"/dev/ttyACM0","activated":"now"})"
                  "\r\n" +
                  kRmc);
        QByteArray got;
        QTRY_VERIFY((got = [&] {
                        QByteArray all;
                        for (const auto &args : received) all += args.at(0).toByteArray();
                        return all;
                    }()) == kGga + kRmc);
        QVERIFY(!t.write("$PNVGVER*4E\r\n")); // gpsd owns the port
        QVERIFY(t.description().contains("/dev/ttyACM0"));
    }

    void aCommandThroughGpsdFailsWithTheReason() {
        FakeGpsd gpsd;
        Connection c(std::make_unique<GpsdTransport>(target(gpsd.port())),
                     gnss::test::builtinRegistry());
        QSignalSpy opened(&c, &Connection::opened);
        QVERIFY(c.open());
        QVERIFY(opened.wait(5000));
        c.commands()->enqueue("PNVGVER");
        QTRY_VERIFY(!c.commands()->history().isEmpty());
        const CommandResult r = c.commands()->history().first();
        QCOMPARE(r.outcome, CommandOutcome::Failed);
        QVERIFY2(r.detail.contains("gpsd owns the port"), qPrintable(r.detail));
    }

    void decodedThroughAConnection() {
        FakeGpsd gpsd;
        Connection c(std::make_unique<GpsdTransport>(target(gpsd.port())),
                     gnss::test::builtinRegistry());
        int gga = 0, rmc = 0;
        connect(c.stream(), &SentenceStream::sentenceDecoded, this, [&](const SentenceEvent &e) {
            if (!e.message) return;
            if (e.sentence.type() == "GGA") ++gga;
            if (e.sentence.type() == "RMC") ++rmc;
        });
        QSignalSpy opened(&c, &Connection::opened);
        QVERIFY(c.open());
        QVERIFY(opened.wait(5000));
        gpsd.send(kGga + kRmc +
                  R"({"class":"ERROR","message":"nothing"})"
                  "\r\n" +
                  kGga);
        QTRY_COMPARE(gga, 2);
        QCOMPARE(rmc, 1);
    }

    void aDeviceGpsdDoesNotHaveIsRefusedInWords() {
        FakeGpsd gpsd;
        GpsdTransport t(target(gpsd.port(), "/dev/ttyS7"));
        QSignalSpy error(&t, &Transport::errorOccurred);
        QVERIFY(t.open());
        QVERIFY(error.wait(5000));
        QCOMPARE(t.state(), Transport::State::Closed);
        QVERIFY2(t.errorString().contains("/dev/ttyS7") && t.errorString().contains("/dev/ttyUSB0"),
                 qPrintable(t.errorString()));
    }

    void aServerThatIsNotGpsdIsNamedSo() {
        FakeGpsd notGpsd;
        notGpsd.greeting = kGga; // a receiver's TCP server talks at once
        GpsdTransport t(target(notGpsd.port()));
        QSignalSpy error(&t, &Transport::errorOccurred);
        QVERIFY(t.open());
        QVERIFY(error.wait(5000));
        QCOMPARE(t.state(), Transport::State::Closed);
        QVERIFY2(t.errorString().contains("not gpsd"), qPrintable(t.errorString()));
    }

    void nobodyListeningSaysIsGpsdRunning() {
        quint16 port;
        {
            QTcpServer s;
            s.listen(QHostAddress::LocalHost);
            port = s.serverPort();
        }
        GpsdTransport t(target(port));
        QSignalSpy error(&t, &Transport::errorOccurred);
        QVERIFY(t.open()); // never blocks: the refusal comes later
        QVERIFY(error.wait(5000));
        QVERIFY2(t.errorString().contains("is gpsd running"), qPrintable(t.errorString()));
    }

    void gpsdGoingAwayIsALostLink() {
        auto gpsd = std::make_unique<FakeGpsd>();
        GpsdTransport t(target(gpsd->port()));
        QVERIFY(t.open());
        QTRY_COMPARE(t.state(), Transport::State::Open);
        gpsd->client->disconnectFromHost();
        QTRY_COMPARE(t.state(), Transport::State::Lost);
        QVERIFY(t.errorString().contains("gpsd closed the connection"));
    }
};

QTEST_GUILESS_MAIN(TstGpsdTransport)
#include "tst_gpsd_transport.moc"
