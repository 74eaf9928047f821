// The other correction sources: a raw TCP port (a test server, then gnss-sim --rtcm-base
// --tcp), a radio modem's serial port (gnss-sim --rtcm-base --pty) and a recorded file played
// at its pace with a speed factor.
#include "corrections/corrections_monitor.h"
#include "corrections/file_correction_source.h"
#include "corrections/serial_correction_source.h"
#include "corrections/tcp_correction_source.h"
#include "rtcm_fixtures.h"
#include "sim_tcp_process.h"
#include "source_watch.h"
#include "test_caster.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss;
using namespace gnss::corrections;
using namespace corrections_test;
using State = CorrectionSource::State;

namespace {

// gnss-sim's RTCM base station.
const QStringList kSimBase{"--rtcm-base", "--seed", "3"};

// Writes `content` to `name` below `dir`; the file's path, empty when it could not be written.
QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &content) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(content);
    return path;
}

// `n` epochs of the simulated base station, one after the other: a recorded RTCM file.
QByteArray baseFile(int n) {
    QByteArray file;
    for (const QByteArray &e : baseEpochs(n)) file += e;
    return file;
}

} // namespace

class TstCorrectionSources : public QObject {
    Q_OBJECT
private slots:
    void aRawTcpPortDeliversItsBytesAndIsRetriedWhenItGoes() {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        const quint16 port = server.serverPort();
        QList<QTcpSocket *> clients;
        connect(&server, &QTcpServer::newConnection, [&] {
            while (QTcpSocket *s = server.nextPendingConnection()) clients.append(s);
        });
        TcpCorrectionSource source(QStringLiteral("127.0.0.1"), port);
        source.setReconnectSettings({100, 400, 60000});
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(clients.size(), 1, 2000);
        const QList<QByteArray> epochs = baseEpochs(3);
        clients[0]->write(epochs[0] + epochs[1]);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epochs[0] + epochs[1], 3000);
        QVERIFY(source.statusText().contains("Receiving RTCM from 127.0.0.1:"));

        clients[0]->disconnectFromHost(); // the base's port goes away and comes back
        QTRY_VERIFY_WITH_TIMEOUT(!watch.errors.isEmpty(), 3000);
        QVERIFY2(watch.errors[0].contains("closed the connection"), qPrintable(watch.errors[0]));
        QTRY_COMPARE_WITH_TIMEOUT(clients.size(), 2, 3000);
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Receiving, 3000);
        clients[1]->write(epochs[2]);
        QTRY_COMPARE_WITH_TIMEOUT(watch.data, epochs[0] + epochs[1] + epochs[2], 3000);
    }

    void aRefusedTcpPortIsSaidAndRetried() {
        TcpCorrectionSource source(QStringLiteral("127.0.0.1"), closedPort());
        source.setReconnectSettings({100, 400, 60000});
        SourceWatch watch(source);
        source.start();
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::WaitingToRetry, 5000);
        QVERIFY2(watch.errors[0].contains("refused the connection"), qPrintable(watch.errors[0]));
    }

    void gnssSimBaseOverTcpGivesValidFrames() {
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        gnss::link::test::SimTcpProcess sim(kSimBase);
        QCOMPARE(sim.address, QString("127.0.0.1:%1").arg(sim.port));
        TcpCorrectionSource source(QStringLiteral("127.0.0.1"), sim.port);
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(watch.sawBaseMessages(), 5000);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(0));
        QCOMPARE(watch.monitor.decodeErrors(), std::uint64_t(0));
        QVERIFY(watch.monitor.basePosition());
        QVERIFY(std::fabs(watch.monitor.basePosition()->geodetic->latDeg - 55.7512) < 1e-6);
    }

    void aRadioModemOnASerialPortDeliversFrames() {
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        gnss::link::test::SimProcess sim(kSimBase + QStringList{"--baud", "38400"});
        if (!sim.ok()) QSKIP("gnss-sim gave no pseudo-terminal");
        SerialCorrectionSource source(sim.device, 38400);
        SourceWatch watch(source);
        source.start();
        QCOMPARE(source.state(), State::Receiving);
        QVERIFY2(source.description().endsWith("at 38400 baud"), qPrintable(source.description()));
        QTRY_VERIFY_WITH_TIMEOUT(watch.monitor.messageType(1074, 0).has_value(), 5000);
        QCOMPARE(watch.monitor.crcErrors(), std::uint64_t(0));
        QVERIFY(source.statusText().startsWith("Receiving RTCM from " + sim.device));
    }

    void aMissingSerialPortIsSaidAndRetried() {
        SerialCorrectionSource source(QStringLiteral("/dev/no-such-radio"), 9600);
        source.setReconnectSettings({100, 400, 60000});
        SourceWatch watch(source);
        source.start();
        QCOMPARE(source.state(), State::WaitingToRetry);
        QVERIFY2(watch.errors.value(0).startsWith("Cannot open /dev/no-such-radio at 9600 baud"),
                 qPrintable(watch.errors.value(0)));
        QTRY_VERIFY_WITH_TIMEOUT(watch.errors.size() >= 2, 3000); // tried again
    }

    void aFileIsPlayedAtItsPace_data() {
        QTest::addColumn<double>("speed");
        QTest::addColumn<int>("minMs");
        QTest::addColumn<int>("maxMs");
        QTest::newRow("as recorded: 4 epochs take 3 s") << 1.0 << 2900 << 4500;
        QTest::newRow("four times faster") << 4.0 << 700 << 2000;
    }
    void aFileIsPlayedAtItsPace() {
        QFETCH(double, speed);
        QFETCH(int, minMs);
        QFETCH(int, maxMs);
        QTemporaryDir dir;
        const QByteArray file = baseFile(4);
        const QString path = writeFile(dir, "base.rtcm", file);
        QVERIFY(!path.isEmpty());
        FileCorrectionSource source(path);
        source.setSpeed(speed);
        SourceWatch watch(source);
        QList<qint64> arrivals;
        QElapsedTimer clock;
        connect(&source, &CorrectionSource::dataReceived,
                [&](const QByteArray &) { arrivals.append(clock.elapsed()); });
        clock.start();
        source.start();
        QCOMPARE(int(source.plan().groups.size()), 4);
        QTRY_COMPARE_WITH_TIMEOUT(source.state(), State::Idle, 10000);
        QCOMPARE(watch.data, file);
        QCOMPARE(arrivals.size(), 4);
        QVERIFY2(arrivals.last() >= minMs && arrivals.last() <= maxMs,
                 qPrintable(QString::number(arrivals.last())));
        QVERIFY2(source.statusText().contains("Played base.rtcm to the end"),
                 qPrintable(source.statusText()));
    }

    void aFileIsLoopedWhenAsked() {
        QTemporaryDir dir;
        const QByteArray file = baseFile(2);
        const QString path = writeFile(dir, "loop.rtcm", file);
        QVERIFY(!path.isEmpty());
        FileCorrectionSource source(path);
        source.setSpeed(10);
        source.setLoop(true);
        SourceWatch watch(source);
        source.start();
        QTRY_VERIFY_WITH_TIMEOUT(watch.data.size() >= 3 * file.size(), 5000);
        QVERIFY(watch.data.startsWith(file + file));
        QCOMPARE(source.state(), State::Receiving);
        source.stop();
        QCOMPARE(source.state(), State::Idle);
    }

    void aFileWithoutRtcmOrAMissingFileFails_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("words");
        QTest::newRow("no RTCM in it")
                << QByteArray("$GPGGA,just,nmea*00\r\n") << "holds no RTCM 3 frames";
        QTest::newRow("no such file") << QByteArray() << "Cannot read";
    }
    void aFileWithoutRtcmOrAMissingFileFails() {
        QFETCH(QByteArray, content);
        QFETCH(QString, words);
        QTemporaryDir dir;
        const QString path = dir.filePath("x.rtcm");
        if (!content.isEmpty()) QVERIFY(!writeFile(dir, "x.rtcm", content).isEmpty());
        FileCorrectionSource source(path);
        SourceWatch watch(source);
        source.start();
        QCOMPARE(source.state(), State::Failed);
        QVERIFY2(watch.errors.value(0).contains(words), qPrintable(watch.errors.value(0)));
    }
};

QTEST_GUILESS_MAIN(TstCorrectionSources)
#include "tst_correction_sources.moc"
