// End to end through Debian's gpsd: gnss-sim on a pseudo-terminal, gpsd reading it (read only, in
// the foreground, on 127.0.0.1: gpsd_process.h), and a GpsdTransport in a link::Connection: the
// receiver's GGA and RMC come through gpsd and are assembled into epochs with a position, the
// vendor's own sentences too (so its dialect is recognised), a device gpsd does not have is
// refused in words naming the ones it has (not retried), and gpsd going away is a lost link.
// Skipped when gpsd is not installed. Before any Qt header: it has a member named emit, which Qt
// defines as a macro.
#include "builtin_registry.h"
#include "state/epoch_assembler.h"

#include "builtin/dialects.h"
#include "gpsd_process.h"
#include "link/connection.h"
#include "link/gpsd_transport.h"
#include "link/sentence_stream.h"
#include "sim_process.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss;
using namespace gnss::link;
using gnss::link::test::GpsdProcess;
using gnss::link::test::SimProcess;

namespace {

#define REQUIRE_SIM_AND_GPSD(sim, gpsd)                                                            \
    do {                                                                                           \
        if (link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");                       \
        if (link::test::gpsdPath().isEmpty())                                                      \
            QSKIP("gpsd is not installed (Debian package gpsd)");                                  \
        if (!(sim).ok()) QSKIP(qPrintable("gnss-sim did not start: " + (sim).error));              \
        QVERIFY2((gpsd).ok(), qPrintable((gpsd).error));                                           \
    } while (0)

GpsdTransport::Target at(const GpsdProcess &gpsd, const QString &device = {}) {
    GpsdTransport::Target t;
    t.host = QStringLiteral("127.0.0.1");
    t.port = gpsd.port;
    t.device = device;
    return t;
}

// What a connection decoded: GGA and RMC counts, epochs with a position.
struct Tally {
    int gga = 0, rmc = 0, epochsWithPosition = 0;
    double lat = 0, lon = 0;
    EpochAssembler assembler;
    void watch(Connection &c) {
        QObject::connect(c.stream(), &SentenceStream::sentenceDecoded,
                         [this, &c](const SentenceEvent &e) {
                             if (!e.message) return;
                             if (e.sentence.type() == "GGA") ++gga;
                             if (e.sentence.type() == "RMC") ++rmc;
                             assembler.setDialect(c.stream()->dialect());
                             assembler.add(e.sentence, *e.message, [this](const Epoch &ep) {
                                 if (!ep.lat || !ep.lon) return;
                                 ++epochsWithPosition;
                                 lat = *ep.lat;
                                 lon = *ep.lon;
                             });
                         });
    }
};

} // namespace

class TstGpsdLive : public QObject {
    Q_OBJECT
private slots:
    void epochsComeThroughGpsd() {
        SimProcess sim({"--dialect", "nmea", "--baud", "9600"});
        GpsdProcess gpsd(sim.device, 9600);
        REQUIRE_SIM_AND_GPSD(sim, gpsd);
        Connection c(std::make_unique<GpsdTransport>(at(gpsd)), gnss::test::builtinRegistry());
        Tally tally;
        tally.watch(c);
        QSignalSpy opened(&c, &Connection::opened);
        QVERIFY(c.open());
        QVERIFY2(opened.wait(10000), qPrintable(c.transport()->errorString()));
        auto *t = qobject_cast<GpsdTransport *>(c.transport());
        QVERIFY(t->gpsdRelease().startsWith("3."));
        QVERIFY2(t->gpsdDevices().contains(sim.device), qPrintable(t->gpsdDevices().join(',')));
        QTRY_VERIFY2_WITH_TIMEOUT(tally.epochsWithPosition >= 3,
                                  qPrintable(QStringLiteral("GGA %1, RMC %2, epochs %3; gpsd: %4")
                                                     .arg(tally.gga)
                                                     .arg(tally.rmc)
                                                     .arg(tally.epochsWithPosition)
                                                     .arg(gpsd.output())),
                                  20000);
        QVERIFY(tally.gga >= 3);
        QVERIFY(tally.rmc >= 3);
        QVERIFY(tally.lat != 0 && tally.lon != 0);
        // Only sentences reached the decoder: gpsd's JSON would have been skipped as noise.
        QCOMPARE(c.decoder().malformed(), std::uint64_t(0));
        QCOMPARE(c.decoder().framerStats().bytesSkipped, std::uint64_t(0));
        QVERIFY(!c.transport()->canWrite());
    }

    void theVendorsSentencesComeThroughAndNameTheDialect() {
        SimProcess sim({"--dialect", "nvs", "--baud", "115200"});
        GpsdProcess gpsd(sim.device, 115200);
        REQUIRE_SIM_AND_GPSD(sim, gpsd);
        // Watching the one device by name.
        Connection c(std::make_unique<GpsdTransport>(at(gpsd, sim.device)),
                     gnss::test::builtinRegistry());
        QSignalSpy dialect(&c, &Connection::dialectDetected);
        QVERIFY(c.open());
        QVERIFY2(dialect.wait(20000), qPrintable(c.transport()->errorString()));
        QCOMPARE(dialect.first().at(0).toString(), QString("nvs"));
    }

    void aDeviceGpsdDoesNotHaveIsRefusedInWords() {
        SimProcess sim({"--dialect", "nmea", "--baud", "9600"});
        GpsdProcess gpsd(sim.device, 9600);
        REQUIRE_SIM_AND_GPSD(sim, gpsd);
        Connection c(std::make_unique<GpsdTransport>(at(gpsd, "/dev/ttyNOSUCH0")),
                     gnss::test::builtinRegistry());
        Transport &t = *c.transport();
        QSignalSpy failed(&c, &Connection::openFailed);
        QVERIFY(c.open());
        QVERIFY(failed.wait(10000));
        QCOMPARE(t.state(), Transport::State::Closed);
        // gpsd refuses the watch without naming its devices: they are asked for and named.
        QVERIFY2(t.errorString().contains("/dev/ttyNOSUCH0"), qPrintable(t.errorString()));
        QVERIFY2(t.errorString().contains(sim.device), qPrintable(t.errorString()));
        // The request's fault: not retried, as it would be refused again.
        QVERIFY(t.errorIsRequest());
        QCOMPARE(failed.first().at(1).toInt(), 0);
        QVERIFY(!c.isReconnecting());
    }

    void gpsdStoppingIsALostLinkThatIsRetried() {
        SimProcess sim({"--dialect", "nmea", "--baud", "9600"});
        GpsdProcess gpsd(sim.device, 9600);
        REQUIRE_SIM_AND_GPSD(sim, gpsd);
        Connection c(std::make_unique<GpsdTransport>(at(gpsd)), gnss::test::builtinRegistry());
        c.setReconnectDelays(200, 400);
        QSignalSpy opened(&c, &Connection::opened);
        QSignalSpy lost(&c, &Connection::linkLost);
        QVERIFY(c.open());
        QVERIFY(opened.wait(10000));
        gpsd.stop();
        QVERIFY(lost.wait(5000));
        QVERIFY2(lost.first().at(0).toString().contains("gpsd"),
                 qPrintable(lost.first().at(0).toString()));
        QVERIFY(lost.first().at(1).toInt() > 0); // tried again
    }
};

QTEST_GUILESS_MAIN(TstGpsdLive)
#include "tst_gpsd_live.moc"
