// End to end: gnss-sim on a pseudo-terminal, read and commanded through the real QSerialPort,
// as the application and any serial program would. One receiver family per test function.
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "sim_output.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSerialPort>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

using namespace gnss;
using gnss::test::summarize;

namespace {

class SimProcess {
public:
    explicit SimProcess(const QStringList &args) {
        proc.setProgram(QStringLiteral(GNSS_SIM_PATH));
        proc.setArguments(QStringList{"--pty"} + args);
        proc.start();
    }
    ~SimProcess() {
        port.close();
        proc.terminate();
        if (!proc.waitForFinished(3000)) proc.kill();
    }
    // Reads the device path (first line of stdout) and opens it at `baud`.
    bool open(int baud) {
        if (!proc.waitForStarted(5000)) return false;
        QElapsedTimer t;
        t.start();
        while (!proc.canReadLine() && t.elapsed() < 5000) proc.waitForReadyRead(100);
        device = QString::fromLocal8Bit(proc.readLine()).trimmed();
        if (!device.startsWith("/dev/")) return false;
        port.setPortName(device);
        port.setBaudRate(baud);
        return port.open(QIODevice::ReadWrite);
    }
    // Everything the port delivers within `ms` milliseconds.
    std::string read(int ms) {
        QByteArray all;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            if (port.waitForReadyRead(50)) all += port.readAll();
        }
        all += port.readAll();
        return all.toStdString();
    }
    void send(const std::string &body) {
        port.write(QByteArray::fromStdString(buildSentence(body) + "\r\n"));
        port.waitForBytesWritten(1000);
    }

    QProcess proc;
    QSerialPort port;
    QString device;
};

} // namespace

class TstSimPty : public QObject {
    Q_OBJECT
private slots:
    void nmeaReceiverTalksOnThePrintedDevice() {
        SimProcess sim({"--dialect", "nmea", "--seed", "3"});
        QVERIFY2(sim.open(9600), qPrintable(sim.device + " " + sim.port.errorString()));
        sim.read(1100); // skip what was already on its way
        const auto s = summarize(sim.read(3000), "nmea");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        const int gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 2 && gga <= 4, QByteArray::number(gga)); // 1 Hz
        for (auto t : {"GGA", "GSA", "GSV", "RMC", "VTG", "ZDA"}) QVERIFY2(s.byType.count(t), t);
        QVERIFY(!s.byType.count("GLL"));
        sim.send("GPGPQ,GLL");
        const auto answered = summarize(sim.read(600), "nmea");
        QVERIFY(answered.byType.count("GLL"));
    }
    void aWrongLineSpeedReadsGarbageUntilItIsRight() {
        SimProcess sim({"--dialect", "nmea"});
        QVERIFY(sim.open(9600));
        sim.port.setBaudRate(4800);
        sim.read(300);
        const std::string garbage = sim.read(1500);
        QVERIFY(garbage.size() > 50);
        QCOMPARE(summarize(garbage).lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        sim.read(300);
        QVERIFY(summarize(sim.read(1500)).byType.count("GGA"));
    }
    void nvsReceiverObeysItsCommandsOnThePort() {
        SimProcess sim({"--dialect", "nvs", "--seed", "4"});
        QVERIFY(sim.open(115200));
        sim.read(500);
        auto s = summarize(sim.read(2000), "nvs");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        int gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 9 && gga <= 11, QByteArray::number(gga)); // 5 Hz
        QVERIFY(s.byType.count("PNVGBSS") && s.byType.count("GSV"));
        // PVT rate 1 Hz: answered, and the output slows down.
        sim.send("PNVGRTK,PVTRATE,1");
        s = summarize(sim.read(700), "nvs");
        const auto rtk = s.all("PNVGRTK");
        QVERIFY(!rtk.empty());
        QCOMPARE(QString::fromStdString(rtk.front()),
                 QString::fromStdString(buildSentence("PNVGRTK,PVTRATE,1")));
        s = summarize(sim.read(3000), "nvs");
        gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 2 && gga <= 4, QByteArray::number(gga));
        // Output list: only RMC and PNVGDOP from now on.
        sim.send("PNVGRZB");
        sim.send("PNVGRZB,RMC,1,PNVGDOP,1");
        sim.read(1200);
        s = summarize(sim.read(2100), "nvs");
        QVERIFY(!s.byType.count("GGA"));
        QVERIFY(s.byType.count("RMC") && s.byType.count("PNVGDOP"));
        // Baud change: the answer comes at 115200, then only 9600 reads sentences.
        sim.send("PNVGRZA,0,9600,1");
        s = summarize(sim.read(500), "nvs");
        QVERIFY(!s.all("PNVGRZA").empty());
        QCOMPARE(summarize(sim.read(1500), "nvs").lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        sim.read(1100);
        QVERIFY(summarize(sim.read(1500), "nvs").byType.count("RMC"));
    }
    void geostarReceiverObeysItsCommandsOnThePort() {
        SimProcess sim({"--dialect", "geostar", "--seed", "5"});
        QVERIFY(sim.open(115200));
        sim.read(300);
        auto s = summarize(sim.read(2600), "geostar");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        int gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 2 && gga <= 3, QByteArray::number(gga)); // 1 Hz
        QVERIFY(s.byType.count("GSA") && s.byType.count("GSV") && s.byType.count("DTM"));
        QVERIFY(!s.byType.count("RMC"));
        // NQUERY answered with the output list; RMC ON and RATE05 change it.
        sim.send("GPSGG,NQUERY");
        s = summarize(sim.read(600), "geostar");
        QVERIFY(!s.all("GPSGG").empty());
        sim.send("GPSGG,RMC ON");
        sim.send("GPSGG,RATE05");
        sim.send("GPSGG,NMEAV4");
        sim.read(600);
        s = summarize(sim.read(2000), "geostar");
        gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 8 && gga <= 11, QByteArray::number(gga)); // 5 Hz
        QVERIFY(s.byAddress.count("GNRMC") && s.byAddress.count("GLGSV"));
        // BDR009: no answer, the port switches; then only 9600 reads sentences.
        sim.send("GPSGG,BDR009");
        sim.read(300);
        QCOMPARE(summarize(sim.read(1200), "geostar").lines.size(), std::size_t(0));
        sim.port.setBaudRate(9600);
        sim.read(600);
        sim.send("GPSGG,RQUERY");
        s = summarize(sim.read(1500), "geostar");
        QVERIFY(s.byType.count("GGA"));
        QVERIFY(!s.all("GPSGG").empty());
    }
    void nemerixReceiverObeysItsCommandsOnThePort() {
        SimProcess sim({"--dialect", "nemerix", "--seed", "6"});
        QVERIFY(sim.open(9600));
        sim.read(300);
        auto s = summarize(sim.read(3200), "nemerix");
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
        const int gga = s.byType.count("GGA") ? s.byType.at("GGA") : 0;
        QVERIFY2(gga >= 3 && gga <= 4, QByteArray::number(gga)); // 1 Hz
        QVERIFY(s.byType.count("RMC") && s.byType.count("VTG") && !s.byType.count("ZDA"));
        // Nemerix takes commands without a checksum too.
        sim.port.write("$PNMRX103,ZDA,1,GGA,0\r\n");
        sim.port.waitForBytesWritten(1000);
        sim.read(1100);
        s = summarize(sim.read(2100), "nemerix");
        QVERIFY(s.byType.count("ZDA") && !s.byType.count("GGA"));
        sim.send("PNMRX603");
        s = summarize(sim.read(800), "nemerix");
        QCOMPARE(s.all("PNMRX603").size(), std::size_t(5));
        sim.send("PNMRX100,0,4800,0");
        sim.read(300);
        QCOMPARE(summarize(sim.read(1200), "nemerix").lines.size(), std::size_t(0));
        sim.port.setBaudRate(4800);
        sim.read(1100);
        QVERIFY(summarize(sim.read(2100), "nemerix").byType.count("RMC"));
    }
    void tcpServesOneClientAtATime() {
        quint16 port = 0;
        {
            QTcpServer probe; // a free port
            QVERIFY(probe.listen(QHostAddress::LocalHost));
            port = probe.serverPort();
        }
        QProcess p;
        p.start(QStringLiteral(GNSS_SIM_PATH),
                {"--dialect", "geostar", "--tcp", QString::number(port), "--speed", "5"});
        QVERIFY(p.waitForStarted());
        QVERIFY(p.waitForReadyRead(3000));
        QCOMPARE(p.readLine().trimmed(), QByteArray("127.0.0.1:") + QByteArray::number(port));
        QTcpSocket sock;
        sock.connectToHost(QHostAddress::LocalHost, port);
        QVERIFY(sock.waitForConnected(3000));
        QByteArray got;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 1500)
            if (sock.waitForReadyRead(100)) got += sock.readAll();
        auto s = summarize(got.toStdString(), "geostar");
        QVERIFY(s.byType.count("GGA") >= 1);
        QCOMPARE(s.checksumErrors, 0);
        sock.write(QByteArray::fromStdString(buildSentence("GPSGG,NQUERY") + "\r\n"));
        got.clear();
        t.restart();
        while (t.elapsed() < 800)
            if (sock.waitForReadyRead(100)) got += sock.readAll();
        QVERIFY(got.contains("$GPSGG,NQUERY,1,"));
        sock.disconnectFromHost();
        p.terminate();
        QVERIFY(p.waitForFinished(3000));
    }
    void hangupFaultDropsTheLine_data() {
        QTest::addColumn<QString>("transport");
        QTest::newRow("pty") << "pty";
        QTest::newRow("tcp") << "tcp";
    }
    void hangupFaultDropsTheLine() {
        QFETCH(QString, transport);
        if (transport == "pty") {
            SimProcess sim({"--dialect", "nemerix", "--faults", "hangup=1.5"});
            QVERIFY(sim.open(9600));
            QVERIFY(summarize(sim.read(1200), "nemerix").byType.count("GGA"));
            QVERIFY(sim.proc.waitForFinished(3000)); // the simulator closes the line and ends
            QCOMPARE(sim.proc.exitCode(), 0);
            return;
        }
        quint16 port = 0;
        {
            QTcpServer probe;
            QVERIFY(probe.listen(QHostAddress::LocalHost));
            port = probe.serverPort();
        }
        QProcess p;
        p.start(QStringLiteral(GNSS_SIM_PATH),
                {"--dialect", "nmea", "--tcp", QString::number(port), "--faults", "hangup=1.5"});
        QVERIFY(p.waitForStarted());
        QVERIFY(p.waitForReadyRead(3000));
        QTcpSocket sock;
        sock.connectToHost(QHostAddress::LocalHost, port);
        QVERIFY(sock.waitForConnected(3000));
        QElapsedTimer t;
        t.start();
        QByteArray got;
        while (sock.state() == QAbstractSocket::ConnectedState && t.elapsed() < 4000)
            if (sock.waitForReadyRead(100)) got += sock.readAll();
        QCOMPARE(sock.state(), QAbstractSocket::UnconnectedState); // the peer hung up
        QVERIFY(t.elapsed() < 3000);
        QVERIFY(got.contains("GGA"));
        QVERIFY(p.waitForFinished(3000));
    }
    void stdoutModeStopsWhenStdinCloses() {
        QProcess p;
        p.start(QStringLiteral(GNSS_SIM_PATH), {"--dialect", "nmea", "--stdout", "--speed", "10"});
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
        p.start(QStringLiteral(GNSS_SIM_PATH), {"--dialect", "nope"});
        QVERIFY(p.waitForFinished(3000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().contains("unknown dialect"));
    }
};

QTEST_GUILESS_MAIN(TstSimPty)
#include "tst_sim_pty.moc"
