// Every server of the project listens on 127.0.0.1 only: gnss-sim --tcp, gnss-cli play --tcp,
// the window's Play Out to TCP (LogPlayer), and the test servers (the test caster, gpsd as the
// tests start it). Checked from outside, in the kernel's socket table (/proc/net/tcp and tcp6:
// no 0.0.0.0, no ::), and by connecting to the port through this machine's other addresses,
// when it has any: refused. (RTKLIB's str2str binds 0.0.0.0; that is documented, not ours.)
#include "builtin_registry.h"
#include "core/sentence_builder.h"
#include "gpsd_process.h"
#include "gui/log_player.h"
#include "listen_table.h"
#include "local_port.h"
#include "logview/log_view.h"
#include "sim_process.h"
#include "sim_tcp_process.h"
#include "test_caster.h"

#include <QProcess>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using gnss::test::listensOnLoopbackOnly;
using gnss::test::outwardAddresses;

namespace {

// A sentence with its checksum (the product's builder) and its line end.
QByteArray sentence(const QByteArray &body) {
    return QByteArray::fromStdString(gnss::buildSentence(body.toStdString())) + "\r\n";
}

// A short NMEA log (GGA and RMC, one epoch a second) for the players.
QByteArray nmeaLog(int seconds) {
    QByteArray out;
    for (int s = 0; s < seconds; ++s) {
        const QByteArray t = QByteArray("1042") + QByteArray::number(s).rightJustified(2, '0');
        out += sentence("GPGGA," + t + ".00,5545.0720,N,03737.1040,E,1,08,0.9,152.0,M,14.0,M,,");
        out += sentence("GPRMC," + t + ".00,A,5545.0720,N,03737.1040,E,0.0,0.0,150324,,,A");
    }
    return out;
}

// Checks `port` from outside: listened to on loopback addresses only; a connection through any
// other address of this machine is refused.
void checkLoopbackOnly(quint16 port) {
    QString seen;
    QTRY_VERIFY2_WITH_TIMEOUT(listensOnLoopbackOnly(port, &seen),
                              qPrintable(QStringLiteral("port %1: %2").arg(port).arg(seen)), 20000);
    for (const QHostAddress &a : outwardAddresses()) {
        QTcpSocket s;
        s.connectToHost(a, port);
        const bool connected = s.waitForConnected(5000);
        QVERIFY2(!connected, qPrintable(a.toString() + " reached it"));
    }
}

} // namespace

class TstLoopbackListen : public QObject {
    Q_OBJECT
private slots:
    // The check itself: a server on every address (IPv4 and IPv6) is seen as such.
    void theCheckSeesAServerOnEveryAddress_data() {
        QTest::addColumn<QHostAddress>("address");
        QTest::addColumn<bool>("loopbackOnly");
        QTest::newRow("0.0.0.0") << QHostAddress(QHostAddress::AnyIPv4) << false;
        QTest::newRow("any (IPv6 and IPv4)") << QHostAddress(QHostAddress::Any) << false;
        QTest::newRow("127.0.0.1") << QHostAddress(QHostAddress::LocalHost) << true;
    }
    void theCheckSeesAServerOnEveryAddress() {
        QFETCH(QHostAddress, address);
        QFETCH(bool, loopbackOnly);
        QTcpServer server;
        if (!server.listen(address)) QSKIP(qPrintable(server.errorString()));
        QString seen;
        QCOMPARE(listensOnLoopbackOnly(server.serverPort(), &seen), loopbackOnly);
        QVERIFY2(!seen.isEmpty(), "nobody seen listening");
        server.close(); // (at once: it was never reachable from outside but for this check)
    }

    void gnssSimTcp() {
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        gnss::link::test::SimTcpProcess sim({"--dialect", "nmea"});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        checkLoopbackOnly(sim.port);
    }

    void gnssCliPlayTcp() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile log(dir.filePath("drive.nmea"));
        QVERIFY(log.open(QIODevice::WriteOnly));
        log.write(nmeaLog(20));
        log.close();
        const quint16 port = gnss::test::closedPort();
        QProcess play;
        play.start(QStringLiteral(GNSS_CLI_PATH),
                   {"play", "--tcp", QString::number(port), log.fileName()});
        QVERIFY(play.waitForStarted(20000));
        QByteArray err;
        QTRY_VERIFY2_WITH_TIMEOUT((err += play.readAllStandardError()).contains("listening on"),
                                  err.constData(), 20000);
        QVERIFY2(err.contains("listening on 127.0.0.1:" + QByteArray::number(port)),
                 err.constData());
        checkLoopbackOnly(port);
        play.kill();
        play.waitForFinished();
    }

    void theWindowsPlayOutToTcp() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("drive.nmea");
        QFile log(path);
        QVERIFY(log.open(QIODevice::WriteOnly));
        log.write(nmeaLog(20));
        log.close();
        auto view = std::make_shared<gnss::logview::LogView>(gnss::test::builtinRegistry());
        view->open(QFile::encodeName(path).toStdString());
        QVERIFY(view->waitUntilIndexed(60000));
        QVERIFY(view->epochCount() > 2);
        gnss::app::LogPlayer player;
        gnss::app::LogPlayer::Target tcp;
        tcp.kind = gnss::app::LogPlayer::Target::Kind::Tcp;
        tcp.tcpPort = gnss::test::closedPort();
        QString why;
        QVERIFY2(player.start(view, 0, view->epochCount() - 1, 1, true, tcp, &why),
                 qPrintable(why));
        checkLoopbackOnly(tcp.tcpPort);
        player.stop();
    }

    void theTestCaster() {
        corrections_test::TstCaster caster;
        QVERIFY(caster.listen());
        checkLoopbackOnly(caster.port());
    }

    void gpsdAsTheTestsStartIt() {
        if (gnss::link::test::gpsdPath().isEmpty()) QSKIP("gpsd is not installed");
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        gnss::link::test::SimProcess sim({"--dialect", "nmea", "--baud", "9600"});
        QVERIFY2(sim.ok(), qPrintable(sim.error));
        gnss::link::test::GpsdProcess gpsd(sim.device, 9600);
        if (!gpsd.ok()) QSKIP(qPrintable(gpsd.error));
        checkLoopbackOnly(gpsd.port);
    }
};

QTEST_MAIN(TstLoopbackListen)
#include "tst_loopback_listen.moc"
