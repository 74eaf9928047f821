// MountMonitor: the source-table record of a served stream from its frames: message types and
// their periods as source tables write them, systems, carrier, the station's position, bit rate.
#include "serve/mount_monitor.h"

#include "rtcm/rtcm_framer.h"
#include "sim/rtcm_base_station.h"

#include <QTest>

using namespace gnss;
using namespace gnss::serve;

namespace {

// `count` epochs of the simulated base, epoch i fed at i × stepMs.
MountMonitor fed(int count, std::int64_t stepMs, sim::BaseStationConfig config = {}) {
    sim::RtcmBaseStation base(config);
    MountMonitor m;
    rtcm::RtcmFramer framer;
    for (int i = 0; i < count; ++i) {
        base.advance(i == 0 ? 0.0 : 1.0);
        framer.feed(base.takeOutput(), [&](const rtcm::RtcmFrame &f) { m.frame(f, i * stepMs); });
    }
    return m;
}

} // namespace

class TstMountMonitor : public QObject {
    Q_OBJECT
private slots:
    void periodsAreWrittenAsSourceTablesWriteThem_data() {
        QTest::addColumn<qint64>("stepMs");
        QTest::addColumn<QString>("details");
        QTest::newRow("every second") << qint64(1000) << "1005(1),1074(1),1084(1),1230(10)";
        QTest::newRow("every ten seconds") << qint64(10000) << "1005(10),1074(10),1084(10)";
        QTest::newRow("twice a second: rounded up to 1")
                << qint64(500) << "1005(1),1074(1),1084(1),1230(5)";
    }
    void periodsAreWrittenAsSourceTablesWriteThem() {
        QFETCH(qint64, stepMs);
        QFETCH(QString, details);
        const int epochs = 30;
        const MountMonitor m = fed(epochs, stepMs);
        const std::int64_t now = (epochs - 1) * stepMs;
        QCOMPARE(QString::fromStdString(m.formatDetails(now)), details);
        QCOMPARE(m.navSystem(now), std::string("GPS+GLO"));
        QCOMPARE(m.carrier(now), 2);
    }

    void theStationIsReadFrom1005() {
        sim::BaseStationConfig c;
        c.latDeg = -33.8688;
        c.lonDeg = 151.2093;
        c.stationId = 77;
        const MountMonitor m = fed(3, 1000, c);
        QCOMPARE(m.station(), std::optional<unsigned>(77));
        QVERIFY(std::fabs(*m.latitude() - c.latDeg) < 1e-6);
        QVERIFY(std::fabs(*m.longitude() - c.lonDeg) < 1e-6);
        ntrip::StreamEntry e;
        m.describe(e, 2000);
        QCOMPARE(e.format, std::string("RTCM 3.3"));
        QCOMPARE(*e.latitude, *m.latitude());
        QVERIFY(*e.bitrate > 0);
    }

    void aTypeSeenOnceHasNoPeriodAndOldOnesLeave() {
        const MountMonitor m = fed(1, 1000);
        QCOMPARE(m.formatDetails(0), std::string("1005,1074,1084,1230"));
        QCOMPARE(m.bitrate(0), 0);
        QCOMPARE(m.formatDetails(MountMonitor::kWindowMs + 1), std::string());
        QCOMPARE(m.carrier(MountMonitor::kWindowMs + 1), 0);
    }
};

QTEST_APPLESS_MAIN(TstMountMonitor)
#include "tst_mount_monitor.moc"
