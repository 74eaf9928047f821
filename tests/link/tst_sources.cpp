// The other sources behind the same interface: the in-process simulator (baud detection, vendor
// detection and a command without any serial port) and a TCP client against gnss-sim --tcp.
#include "baud_detector.h"
#include "command_queue.h"
#include "dialects.h"
#include "sim_process.h"
#include "tcp_transport.h"
#include "vendor_detector.h"
#ifdef GNSS_HAVE_SIM
#include "simulator_transport.h"
#endif

#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

using namespace gnss;
using namespace gnss::link;

namespace {

const DialectRegistry &registry() {
    static const DialectRegistry r = makeBuiltinRegistry();
    return r;
}

} // namespace

class TstSources : public QObject {
    Q_OBJECT
private slots:
    void inProcessSimulatorIsDetectedAndCommanded() {
#ifndef GNSS_HAVE_SIM
        QSKIP("gnss_sim is not built");
#else
        SimulatorTransport sim(QStringLiteral("nvs"), 3, 9600); // receiver at 115200
        QVERIFY2(sim.open(), qPrintable(sim.errorString()));
        BaudDetector baud(&sim);
        baud.setListenMs(500);
        QSignalSpy baudDone(&baud, &BaudDetector::finished);
        baud.start();
        QVERIFY(baudDone.wait(15000));
        QVERIFY2(baud.result().found, qPrintable(baud.result().error));
        QCOMPARE(baud.result().baud, 115200);

        VendorDetector vendor(&sim, registry());
        QSignalSpy vendorDone(&vendor, &VendorDetector::finished);
        vendor.start();
        QVERIFY(vendorDone.wait(10000));
        QCOMPARE(vendor.result().dialect, QStringLiteral("nvs"));
        QVERIFY(!vendor.result().firmware.isEmpty());

        CommandQueue q(&sim);
        q.setDialect(registry().find("nvs"));
        q.enqueue("PNVGVER");
        QTRY_COMPARE_WITH_TIMEOUT(q.history().size(), 1, 5000);
        QCOMPARE(int(q.history().first().outcome), int(CommandOutcome::Accepted));
#endif
    }

    void tcpClientReadsGnssSimAndNoticesItLeaving() {
        if (test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        QTcpServer probe; // a free port for the simulator
        QVERIFY(probe.listen(QHostAddress::LocalHost));
        const quint16 port = probe.serverPort();
        probe.close();
        QProcess sim;
        sim.start(test::simPath(), {"--dialect", "nmea", "--tcp", QString::number(port)});
        QVERIFY(sim.waitForReadyRead(5000)); // it prints its address once listening
        TcpTransport tcp(QStringLiteral("127.0.0.1"), port);
        QVERIFY2(tcp.open(), qPrintable(tcp.errorString()));
        QByteArray got;
        connect(&tcp, &Transport::bytesReceived, [&](const QByteArray &b) { got += b; });
        QTRY_VERIFY_WITH_TIMEOUT(got.contains("GGA,"), 5000);
        QSignalSpy state(&tcp, &Transport::stateChanged);
        sim.terminate();
        sim.waitForFinished(3000);
        QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Transport::State::Lost, 5000);
        QVERIFY(!tcp.errorString().isEmpty());
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
