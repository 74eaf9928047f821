// NtripSource against a real NTRIP 1 caster: Debian's str2str (RTKLIB 2.4.3) as
//   str2str -in tcpsvr://:IN -out 'ntripc://rover7:s3cret-pw@:PORT/MOUNT:MOUNT;RTCM 3.2;...' -b 1
// fed by the test (frames pushed into IN) or by gnss-sim --rtcm-base --tcp. What RTKLIB's
// caster does, found by trying it: "ICY 200 OK" and data, also to an HTTP/1.1 (NTRIP 2)
// request; a bare "HTTP/1.0 401 Unauthorized" line then close for a wrong password; its source
// table for an unknown mountpoint; bytes a client sends after the OK (the GGA) are relayed back
// to the input (-b 1), while bytes sent with the request are lost (so the GGA goes up after the
// reply). Skipped when str2str is not installed.
#include "corrections/corrections_monitor.h"
#include "corrections/ntrip_source.h"
#include "rtcm_fixtures.h"
#include "sim_tcp_process.h"
#include "source_watch.h"
#include "test_caster.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpSocket>
#include <QTest>

#include <memory>

using namespace gnss;
using namespace gnss::corrections;
using namespace corrections_test;
using State = CorrectionSource::State;

namespace {

QString str2strPath() {
    return QStandardPaths::findExecutable(QStringLiteral("str2str"));
}

// Whether something accepts connections on 127.0.0.1:port (closed again at once).
bool accepts(quint16 port) {
    QTcpSocket s;
    s.connectToHost(QStringLiteral("127.0.0.1"), port);
    const bool ok = s.waitForConnected(200);
    s.abort();
    return ok;
}

bool waitUntilAccepting(quint16 port, int ms) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        if (accepts(port)) return true;
        QTest::qWait(50);
    }
    return false;
}

// str2str as an NTRIP 1 caster on `casterPort`, reading `input` (an RTKLIB stream path).
struct Str2StrCaster {
    QProcess proc;
    quint16 casterPort = 0;
    bool ok = false;
    Str2StrCaster(const QString &input, quint16 port) : casterPort(port) {
        proc.setProcessChannelMode(QProcess::MergedChannels);
        proc.start(str2strPath(),
                   {"-in", input, "-out",
                    QString("ntripc://rover7:s3cret-pw@:%1/MOUNT:MOUNT;RTCM 3.2;1005(10);2;GPS;"
                            "LOCAL;XXX;0.00;0.00;0;0;sim;none;B;N;9600;")
                            .arg(port),
                    "-b", "1"});
        ok = proc.waitForStarted(5000) && waitUntilAccepting(port, 5000);
    }
    ~Str2StrCaster() { stop(); }
    // str2str clears its stop flag when its main loop begins, so a SIGTERM that arrives while
    // it is still starting is forgotten: it is sent again until it takes.
    void stop() {
        for (int i = 0; i < 15 && proc.state() != QProcess::NotRunning; ++i) {
            proc.terminate();
            proc.waitForFinished(200);
        }
        if (proc.state() != QProcess::NotRunning) {
            proc.kill();
            proc.waitForFinished(3000);
        }
    }
};

// gnss-sim's base station over TCP, and str2str as the caster of its stream.
struct SimBaseCaster {
    gnss::link::test::SimTcpProcess base{{"--rtcm-base"}};
    Str2StrCaster caster{"tcpcli://" + base.address, closedPort()};
    // Whether both run; if not, why.
    bool ok() const { return base.ok() && caster.ok; }
    QByteArray why() const {
        return base.ok() ? "str2str did not start" : base.error.toLocal8Bit();
    }
};

// The caster fed by the test: frames pushed into str2str's input port. A port found free can be
// taken by another suite's connection before str2str binds it ("stream server start error"):
// then it is tried again on other ports.
struct FedCaster {
    quint16 inPort = 0;
    std::unique_ptr<Str2StrCaster> started;
    QTcpSocket input;
    QByteArray relayed; // what str2str relays back from the caster's clients (-b 1)
    bool ok = false;
    FedCaster() {
        QObject::connect(&input, &QTcpSocket::readyRead, [this] { relayed += input.readAll(); });
        for (int attempt = 0; attempt < 3 && !ok; ++attempt) {
            inPort = closedPort();
            started = std::make_unique<Str2StrCaster>(QString("tcpsvr://:%1").arg(inPort),
                                                      closedPort());
            if (!started->ok) continue;
            input.connectToHost(QStringLiteral("127.0.0.1"), inPort);
            ok = input.waitForConnected(3000);
            if (!ok) input.abort();
        }
    }
    Str2StrCaster &caster() { return *started; }
};

NtripSettings settings(quint16 port, int version = 1) {
    NtripSettings s;
    s.host = QStringLiteral("127.0.0.1");
    s.port = port;
    s.mountpoint = QStringLiteral("MOUNT");
    s.user = QStringLiteral("rover7");
    s.password = QStringLiteral("s3cret-pw");
    s.version = ntrip::NtripVersion(version);
    return s;
}

#define REQUIRE_STR2STR()                                                                          \
    do {                                                                                           \
        if (str2strPath().isEmpty()) QSKIP("str2str (Debian package rtklib) is not installed");    \
    } while (0)

} // namespace

class TstNtripStr2str : public QObject {
    Q_OBJECT
private slots:
    void framesPushedIntoTheCasterArriveByteExact() {
        REQUIRE_STR2STR();
        FedCaster fed;
        QVERIFY2(fed.ok, fed.caster().proc.readAll().constData());
        NtripSource source(settings(fed.caster().casterPort));
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QVERIFY2(source.statusText().contains("(NTRIP 1 (ICY))"), qPrintable(source.statusText()));
        QTest::qWait(200); // str2str takes the client on at its next cycle
        QByteArray sent;
        for (const QByteArray &epoch : baseEpochs(5)) {
            fed.input.write(epoch);
            sent += epoch;
            QTest::qWait(50);
        }
        QTRY_COMPARE_WITH_TIMEOUT(watch.data.size(), sent.size(), 5000);
        QCOMPARE(watch.data, sent);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(0));
        QCOMPARE(watch.monitor.messageType(1074, 0)->count, std::uint64_t(5));
    }

    // A request str2str refuses: the reason in words, and no secret in them.
    void aRefusalIsSaidInWords_data() {
        QTest::addColumn<QString>("password");
        QTest::addColumn<QString>("mountpoint");
        QTest::addColumn<QStringList>("words");
        QTest::addColumn<QStringList>("unsaid");
        QTest::newRow("a wrong password")
                << "not-the-password"
                << "MOUNT"
                << QStringList{"refused the user name or password for mountpoint MOUNT (401 "
                               "Unauthorized, HTTP/1.0 reply)"}
                << QStringList{"not-the-password", "rover7"};
        QTest::newRow("an unknown mountpoint")
                << "s3cret-pw"
                << "NOPE"
                << QStringList{"Mountpoint NOPE is not on", "(NTRIP 1 (SOURCETABLE) reply)"}
                << QStringList{};
    }
    void aRefusalIsSaidInWords() {
        QFETCH(QString, password);
        QFETCH(QString, mountpoint);
        QFETCH(QStringList, words);
        QFETCH(QStringList, unsaid);
        REQUIRE_STR2STR();
        FedCaster fed;
        QVERIFY(fed.ok);
        NtripSettings s = settings(fed.caster().casterPort);
        s.password = password;
        s.mountpoint = mountpoint;
        NtripSource source(s);
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Failed, 5000);
        const QString e = watch.errors.value(0);
        for (const QString &w : words) QVERIFY2(e.contains(w), qPrintable(e));
        for (const QString &secret : unsaid) QVERIFY2(!watch.said(secret), qPrintable(secret));
    }

    void anNtrip2RequestIsAnsweredInNtrip1AndSaidSo() {
        REQUIRE_STR2STR();
        FedCaster fed;
        QVERIFY(fed.ok);
        NtripSource source(settings(fed.caster().casterPort, 2));
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QVERIFY2(source.statusText().contains("asked NTRIP 2, the caster answered NTRIP 1 (ICY)"),
                 qPrintable(source.statusText()));
        QTest::qWait(200);
        const QByteArray epoch = baseEpochs(1).first();
        fed.input.write(epoch);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epoch, 5000); // not chunked: passed as it came
    }

    void theGgaUploadReachesTheCaster() {
        REQUIRE_STR2STR();
        FedCaster fed;
        QVERIFY(fed.ok);
        NtripSettings s = settings(fed.caster().casterPort);
        s.ggaIntervalMs = 300;
        NtripSource source(s);
        source.setRoverPosition(roverPosition());
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(fed.relayed.count("$GPGGA,") >= 2, 5000);
        QVERIFY(fed.relayed.contains(",5545.07200,N,03737.10400,E,1,12,1.0,152.000,M,"));
    }

    void theSourceTableComesFromStr2str() {
        REQUIRE_STR2STR();
        FedCaster fed;
        QVERIFY(fed.ok);
        NtripSource source(settings(fed.caster().casterPort));
        QSignalSpy got(&source, &NtripSource::sourceTableReceived);
        source.fetchSourceTable();
        QVERIFY(got.wait(5000));
        const auto table = got.first().first().value<ntrip::SourceTable>();
        QVERIFY(table.complete);
        QCOMPARE(int(table.streams.size()), 1);
        QCOMPARE(table.streams[0].mountpoint, std::string("MOUNT"));
        QCOMPARE(table.streams[0].format, std::string("RTCM 3.2"));
    }

    void theCasterGoingAwayAndComingBackIsReconnected() {
        REQUIRE_STR2STR();
        const quint16 inPort = closedPort(), port = closedPort();
        auto caster = std::make_unique<Str2StrCaster>(QString("tcpsvr://:%1").arg(inPort), port);
        QVERIFY(caster->ok);
        NtripSource source(settings(port));
        source.setReconnectSettings({200, 800, 60000});
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        caster.reset(); // the caster stops mid-stream
        QTRY_VERIFY_WITH_TIMEOUT(watch.errors.size() >= 2, 5000);
        QVERIFY2(watch.errors[0].contains("closed the connection mid-stream"),
                 qPrintable(watch.errors[0]));
        QVERIFY2(watch.errors[1].contains("refused the connection"), qPrintable(watch.errors[1]));
        caster = std::make_unique<Str2StrCaster>(QString("tcpsvr://:%1").arg(inPort), port);
        QVERIFY(caster->ok);
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QTcpSocket input;
        input.connectToHost(QStringLiteral("127.0.0.1"), inPort);
        QVERIFY(input.waitForConnected(3000));
        QTest::qWait(200);
        const QByteArray epoch = baseEpochs(1).first();
        input.write(epoch);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epoch, 5000);
    }

    void gnssSimBaseThroughStr2str() {
        REQUIRE_STR2STR();
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimBaseCaster chain;
        QVERIFY2(chain.ok(), chain.why().constData());
        NtripSource source(settings(chain.caster.casterPort));
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(watch.sawBaseMessages(), 8000);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(0));
        QCOMPARE(watch.monitor.decodeErrors(), std::uint64_t(0));
    }

    // The whole chain with Debian's caster: gnss-sim's base → str2str (NTRIP 1) → gnss-cli
    // ntrip → the simulated NV08C-RTK on a pseudo-terminal, which is autonomous until the
    // corrections flow, then float, then fixed.
    void gnssCliTakesTheRoverToRtkFixedThroughStr2str() {
        REQUIRE_STR2STR();
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        SimBaseCaster chain;
        QVERIFY2(chain.ok(), chain.why().constData());
        gnss::link::test::SimProcess rover(
                {"--dialect", "nvs", "--speed", "5", "--baud", "460800"});
        QVERIFY2(rover.ok(), qPrintable(rover.error));
        QProcess cli;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("TEST_NTRIP_PW", "s3cret-pw");
        cli.setProcessEnvironment(env);
        cli.start(QStringLiteral(GNSS_CLI_PATH),
                  {"ntrip", "--caster", QString("127.0.0.1:%1").arg(chain.caster.casterPort),
                   "--mount", "MOUNT", "--user", "rover7", "--password-env", "TEST_NTRIP_PW",
                   "--ntrip-version", "1", "--port", rover.device, "--baud", "460800", "--duration",
                   "12"});
        QVERIFY(cli.waitForFinished(30000));
        const QByteArray err = cli.readAllStandardError();
        QVERIFY2(cli.exitCode() == 0, err.constData());
        QStringList fixes;
        for (const QByteArray &line : cli.readAllStandardOutput().split('\n'))
            if (!line.trimmed().isEmpty())
                fixes << QJsonDocument::fromJson(line).object().value("fix").toString();
        QVERIFY2(fixes.contains("3d") && fixes.contains("rtk_float"), err.constData());
        QVERIFY(fixes.indexOf("3d") < fixes.indexOf("rtk_float"));
        QCOMPARE(fixes.last(), QString("rtk_fixed"));
        QVERIFY2(err.contains("NTRIP 1 (ICY)") && err.contains("\"frames_dropped\":0"),
                 err.constData());
        chain.base.stop();
    }
};

QTEST_GUILESS_MAIN(TstNtripStr2str)
#include "tst_ntrip_str2str.moc"
