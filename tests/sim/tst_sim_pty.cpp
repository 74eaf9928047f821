// End to end: gnss-sim on a pseudo-terminal, read and commanded through the real QSerialPort,
// as the application and any serial program would. One receiver family per test function.
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "sim_output.h"
#include "sim_process.h"
#include "sim_tcp_process.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSerialPort>
#include <QTcpSocket>
#include <QTest>

using namespace gnss;
using gnss::test::summarize;

namespace {

using gnss::link::test::SimTcpProcess;
using gnss::test::OutputSummary;

// Everything `device` delivers within `ms` milliseconds.
QByteArray readFor(QIODevice &device, int ms) {
    QByteArray all;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        if (device.waitForReadyRead(50)) all += device.readAll();
    }
    all += device.readAll();
    return all;
}

// gnss-sim on a pseudo-terminal (tests/link/sim_process.h) with the real QSerialPort on it.
class SimPort : public gnss::link::test::SimProcess {
public:
    using SimProcess::SimProcess;
    // Opens the device it printed at `baud`.
    bool open(int baud) {
        if (!ok()) return false;
        port.setPortName(device);
        port.setBaudRate(baud);
        return port.open(QIODevice::ReadWrite);
    }
    // Everything the port delivers within `ms` milliseconds.
    std::string read(int ms) { return readFor(port, ms).toStdString(); }
    // What the receiver says in `ms` milliseconds after `skipMs` (what was already on its way).
    OutputSummary listen(int skipMs, int ms, std::string_view dialect = "auto") {
        read(skipMs);
        return summarize(read(ms), dialect);
    }
    void send(const std::string &body) {
        port.write(QByteArray::fromStdString(buildSentence(body) + "\r\n"));
        port.waitForBytesWritten(1000);
    }

    QSerialPort port;
};

// GGA `min`..`max` times: the receiver's output rate.
void checkGgaCount(const OutputSummary &s, int min, int max) {
    const int gga = s.count("GGA");
    QVERIFY2(gga >= min && gga <= max, QByteArray::number(gga));
}

// A steady stream at its rate: no checksum or decode errors, GGA `min`..`max` times.
void checkSteady(const OutputSummary &s, int min, int max) {
    QCOMPARE(s.checksumErrors, 0);
    QCOMPARE(s.decodeErrors, 0);
    checkGgaCount(s, min, max);
}

} // namespace

class TstSimPty : public QObject {
    Q_OBJECT
private slots:
    void nmeaReceiverTalksOnThePrintedDevice() {
        SimPort sim({"--dialect", "nmea", "--seed", "3"});
        QVERIFY2(sim.open(9600), qPrintable(sim.device + " " + sim.port.errorString()));
        const auto s = sim.listen(1100, 3000, "nmea");
        checkSteady(s, 2, 4); // 1 Hz
        if (QTest::currentTestFailed()) return;
        for (auto t : {"GGA", "GSA", "GSV", "RMC", "VTG", "ZDA"}) QVERIFY2(s.byType.count(t), t);
        QVERIFY(!s.byType.count("GLL"));
        sim.send("GPGPQ,GLL");
        const auto answered = summarize(sim.read(600), "nmea");
        QVERIFY(answered.byType.count("GLL"));
    }
    void aWrongLineSpeedReadsGarbageUntilItIsRight() {
        SimPort sim({"--dialect", "nmea"});
        QVERIFY(sim.open(9600));
        sim.port.setBaudRate(4800);
        sim.read(300);
        const std::string garbage = sim.read(1500);
        QVERIFY(garbage.size() > 50);
        QCOMPARE(summarize(garbage).lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        QVERIFY(sim.listen(300, 1500).byType.count("GGA"));
    }
    void nvsReceiverObeysItsCommandsOnThePort() {
        SimPort sim({"--dialect", "nvs", "--seed", "4"});
        QVERIFY(sim.open(115200));
        auto s = sim.listen(500, 2000, "nvs");
        checkSteady(s, 9, 11); // 5 Hz
        if (QTest::currentTestFailed()) return;
        QVERIFY(s.byType.count("PNVGBSS") && s.byType.count("GSV"));
        // PVT rate 1 Hz: answered, and the output slows down.
        sim.send("PNVGRTK,PVTRATE,1");
        s = summarize(sim.read(700), "nvs");
        const auto rtk = s.all("PNVGRTK");
        QVERIFY(!rtk.empty());
        QCOMPARE(QString::fromStdString(rtk.front()),
                 QString::fromStdString(buildSentence("PNVGRTK,PVTRATE,1")));
        checkGgaCount(summarize(sim.read(3000), "nvs"), 2, 4);
        if (QTest::currentTestFailed()) return;
        // Output list: only RMC and PNVGDOP from now on.
        sim.send("PNVGRZB");
        sim.send("PNVGRZB,RMC,1,PNVGDOP,1");
        s = sim.listen(1200, 2100, "nvs");
        QVERIFY(!s.byType.count("GGA"));
        QVERIFY(s.byType.count("RMC") && s.byType.count("PNVGDOP"));
        // Baud change: the answer comes at 115200, then only 9600 reads sentences.
        sim.send("PNVGRZA,0,9600,1");
        s = summarize(sim.read(500), "nvs");
        QVERIFY(!s.all("PNVGRZA").empty());
        QCOMPARE(summarize(sim.read(1500), "nvs").lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        QVERIFY(sim.listen(1100, 1500, "nvs").byType.count("RMC"));
    }
    void geostarReceiverObeysItsCommandsOnThePort() {
        SimPort sim({"--dialect", "geostar", "--seed", "5"});
        QVERIFY(sim.open(115200));
        auto s = sim.listen(300, 2600, "geostar");
        checkSteady(s, 2, 3); // 1 Hz
        if (QTest::currentTestFailed()) return;
        QVERIFY(s.byType.count("GSA") && s.byType.count("GSV") && s.byType.count("DTM"));
        QVERIFY(!s.byType.count("RMC"));
        // NQUERY answered with the output list; RMC ON and RATE05 change it.
        sim.send("GPSGG,NQUERY");
        s = summarize(sim.read(600), "geostar");
        QVERIFY(!s.all("GPSGG").empty());
        sim.send("GPSGG,RMC ON");
        sim.send("GPSGG,RATE05");
        sim.send("GPSGG,NMEAV4");
        s = sim.listen(600, 2000, "geostar");
        checkGgaCount(s, 8, 11); // 5 Hz
        if (QTest::currentTestFailed()) return;
        QVERIFY(s.byAddress.count("GNRMC") && s.byAddress.count("GLGSV"));
        // BDR009: no answer, the port switches; then only 9600 reads sentences.
        sim.send("GPSGG,BDR009");
        QCOMPARE(sim.listen(300, 1200, "geostar").lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        sim.read(600);
        sim.send("GPSGG,RQUERY");
        s = summarize(sim.read(1500), "geostar");
        QVERIFY(s.byType.count("GGA"));
        QVERIFY(!s.all("GPSGG").empty());
    }
    void nemerixReceiverObeysItsCommandsOnThePort() {
        SimPort sim({"--dialect", "nemerix", "--seed", "6"});
        QVERIFY(sim.open(9600));
        auto s = sim.listen(300, 3200, "nemerix");
        checkSteady(s, 3, 4); // 1 Hz
        if (QTest::currentTestFailed()) return;
        QVERIFY(s.byType.count("RMC") && s.byType.count("VTG") && !s.byType.count("ZDA"));
        // Nemerix takes commands without a checksum too.
        sim.port.write("$PNMRX103,ZDA,1,GGA,0\r\n");
        sim.port.waitForBytesWritten(1000);
        s = sim.listen(1100, 2100, "nemerix");
        QVERIFY(s.byType.count("ZDA") && !s.byType.count("GGA"));
        sim.send("PNMRX603");
        s = summarize(sim.read(800), "nemerix");
        QCOMPARE(s.all("PNMRX603").size(), std::size_t(5));
        sim.send("PNMRX100,0,4800,0");
        QCOMPARE(sim.listen(300, 1200, "nemerix").lines.size(), std::size_t(0));
        sim.port.setBaudRate(4800);
        QVERIFY(sim.listen(1100, 2100, "nemerix").byType.count("RMC"));
    }
    void tcpServesOneClientAtATime() {
        SimTcpProcess sim({"--dialect", "geostar", "--speed", "5"});
        QCOMPARE(sim.address, QStringLiteral("127.0.0.1:%1").arg(sim.port));
        QTcpSocket sock;
        sock.connectToHost(QHostAddress::LocalHost, sim.port);
        QVERIFY(sock.waitForConnected(3000));
        auto s = summarize(readFor(sock, 1500).toStdString(), "geostar");
        QVERIFY(s.byType.count("GGA") >= 1);
        QCOMPARE(s.checksumErrors, 0);
        sock.write(QByteArray::fromStdString(buildSentence("GPSGG,NQUERY") + "\r\n"));
        QVERIFY(readFor(sock, 800).contains("$GPSGG,NQUERY,1,"));
        sock.disconnectFromHost();
        sim.proc.terminate();
        QVERIFY(sim.proc.waitForFinished(3000));
    }
    void hangupFaultDropsTheLine_data() {
        QTest::addColumn<QString>("transport");
        QTest::newRow("pty") << "pty";
        QTest::newRow("tcp") << "tcp";
    }
    void hangupFaultDropsTheLine() {
        QFETCH(QString, transport);
        if (transport == "pty") {
            // 2.5 s: room for a loaded machine between the device printed and the port opened.
            SimPort sim({"--dialect", "nemerix", "--faults", "hangup=2.5"});
            QVERIFY(sim.open(9600));
            QVERIFY(summarize(sim.read(1200), "nemerix").byType.count("GGA"));
            QVERIFY(sim.proc.waitForFinished(3000)); // the simulator closes the line and ends
            QCOMPARE(sim.proc.exitCode(), 0);
            return;
        }
        SimTcpProcess sim({"--dialect", "nmea", "--faults", "hangup=1.5"});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        QTcpSocket sock;
        sock.connectToHost(QHostAddress::LocalHost, sim.port);
        QVERIFY(sock.waitForConnected(3000));
        QElapsedTimer t;
        t.start();
        QByteArray got;
        while (sock.state() == QAbstractSocket::ConnectedState && t.elapsed() < 4000)
            if (sock.waitForReadyRead(100)) got += sock.readAll();
        QCOMPARE(sock.state(), QAbstractSocket::UnconnectedState); // the peer hung up
        QVERIFY(t.elapsed() < 3000);
        QVERIFY(got.contains("GGA"));
        QVERIFY(sim.proc.waitForFinished(3000));
    }
    void stdoutModeStopsWhenStdinCloses() {
        QProcess p;
        p.start(gnss::link::test::simPath(), {"--dialect", "nmea", "--stdout", "--speed", "10"});
        QVERIFY(p.waitForStarted());
        QTest::qWait(600);
        p.closeWriteChannel();
        QVERIFY(p.waitForFinished(3000));
        QCOMPARE(p.exitCode(), 0);
        const auto s = summarize(p.readAllStandardOutput().toStdString(), "nmea");
        QVERIFY(s.byType.count("GGA") && s.checksumErrors == 0);
    }
    void badCommandLineIsRefused() {
        QProcess p;
        p.start(gnss::link::test::simPath(), {"--dialect", "nope"});
        QVERIFY(p.waitForFinished(3000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().contains("unknown dialect"));
    }
};

QTEST_GUILESS_MAIN(TstSimPty)
#include "tst_sim_pty.moc"
