// The corrections monitor on a fake clock: counts, rates over ten seconds, ages, the meaning
// of each type, the base position from 1005 and 1006 and the rover's baseline, corrupt frames
// and skipped bytes counted, and a bounded history of the correction age.
#include "corrections/corrections_monitor.h"
#include "corrections/rtcm_message_names.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_fixtures.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace gnss;
using namespace gnss::corrections;
using namespace corrections_test;

class TstCorrectionsMonitor : public QObject {
    Q_OBJECT
private slots:
    void eachTypeIsCountedWithItsRateAndAge() {
        CorrectionsMonitor m;
        const QList<QByteArray> epochs = baseEpochs(20);
        for (int i = 0; i < epochs.size(); ++i) m.feed(view(epochs[i]), 100000 + i * 1000);
        const std::int64_t now = 100000 + 19 * 1000 + 400;
        const auto types = m.messageTypes(now);
        QCOMPARE(int(types.size()), 4); // 1005 1074 1084 1230, ascending
        QCOMPARE(types[0].number, 1005u);
        QCOMPARE(types[0].line, std::string("1005: base position"));
        QCOMPARE(types[1].line, std::string("1074: GPS MSM4"));
        QCOMPARE(types[2].line, std::string("1084: GLONASS MSM4"));
        QCOMPARE(types[3].line, std::string("1230: GLONASS biases"));
        QCOMPARE(types[1].count, std::uint64_t(20));
        QCOMPARE(types[1].ratePerSecond, 1.0);
        QCOMPARE(types[3].count, std::uint64_t(2)); // at 0 and 10 s
        QCOMPARE(types[3].ratePerSecond, 0.1);
        QCOMPARE(types[1].ageMs, std::int64_t(400));
        QCOMPARE(types[3].ageMs, std::int64_t(9400));
        QCOMPARE(m.messages(), std::uint64_t(20 * 3 + 2));
        QCOMPARE(m.crcErrors(), std::uint64_t(0));
        QCOMPARE(m.decodeErrors(), std::uint64_t(0));
        std::uint64_t bytes = 0;
        for (const auto &e : epochs) bytes += std::uint64_t(e.size());
        QCOMPARE(m.bytesTotal(), bytes);
        const double perSecond =
                double(bytes -
                       std::uint64_t(epochs[0].size() + epochs[1].size() + epochs[2].size() +
                                     epochs[3].size() + epochs[4].size() + epochs[5].size() +
                                     epochs[6].size() + epochs[7].size() + epochs[8].size() +
                                     epochs[9].size())) /
                10.0;
        QCOMPARE(m.bytesPerSecond(now), perSecond);
    }

    void ratesOfAYoungOrStoppedStream_data() {
        QTest::addColumn<int>("messages");
        QTest::addColumn<int>("everyMs");
        QTest::addColumn<int>("lookAfterMs");
        QTest::addColumn<double>("rate");
        QTest::newRow("10 Hz for 3 s") << 30 << 100 << 0 << 10.0;
        QTest::newRow("1 Hz for 3 s: not under-reported") << 3 << 1000 << 0 << 1.0;
        QTest::newRow("stopped 5 s ago") << 20 << 1000 << 5000 << 0.5;
        QTest::newRow("stopped 11 s ago") << 20 << 1000 << 11000 << 0.0;
    }
    void ratesOfAYoungOrStoppedStream() {
        QFETCH(int, messages);
        QFETCH(int, everyMs);
        QFETCH(int, lookAfterMs);
        QFETCH(double, rate);
        CorrectionsMonitor m;
        rtcm::StationArp arp;
        arp.x = 2845455;
        arp.y = 2160465;
        arp.z = 5265313;
        const QByteArray frame = QByteArray::fromStdString(rtcm::encodeStationArp(arp));
        std::int64_t t = 0;
        for (int i = 0; i < messages; ++i, t += everyMs) m.feed(view(frame), t);
        t -= everyMs;
        QCOMPARE(m.messageType(1005, t + lookAfterMs)->ratePerSecond, rate);
    }

    void theBasePositionComesFrom1005And1006() {
        CorrectionsMonitor m;
        QVERIFY(!m.basePosition());
        rtcm::StationArp arp;
        arp.station = 42;
        const wgs84::Ecef ecef = wgs84::toEcef({55.7512, 37.6184, 166.6});
        arp.x = ecef.x;
        arp.y = ecef.y;
        arp.z = ecef.z;
        m.feed(rtcm::encodeStationArp(arp), 0);
        QVERIFY(m.basePosition());
        QCOMPARE(m.basePosition()->message, 1005u);
        QCOMPARE(m.basePosition()->station, 42u);
        QVERIFY(std::fabs(m.basePosition()->geodetic->latDeg - 55.7512) < 1e-8);
        QVERIFY(std::fabs(m.basePosition()->geodetic->height - 166.6) < 1e-3);
        QVERIFY(!m.baselineMetres()); // no rover yet

        arp.antennaHeight = 1.5;
        m.feed(rtcm::encodeStationArp(arp), 1000);
        QCOMPARE(m.basePosition()->message, 1006u);
        QCOMPARE(m.basePosition()->antennaHeight.value_or(0), 1.5);

        // A rover 3 km north and 4 km east, 0 m up: about 5 km of baseline.
        double lat = 55.7512 + 3000.0 / 111300.0;
        double lon = 37.6184 + 4000.0 / (111300.0 * std::cos(55.7512 * std::numbers::pi / 180));
        m.setRoverPosition({lat, lon, 166.6});
        QVERIFY2(std::fabs(*m.baselineMetres() - 5000) < 30,
                 qPrintable(QString::number(*m.baselineMetres())));
        m.clearRoverPosition();
        QVERIFY(!m.baselineMetres());
    }

    void corruptFramesAndNoiseAreCounted() {
        CorrectionsMonitor m;
        const QList<QByteArray> epochs = baseEpochs(3);
        QByteArray corrupt = epochs[1];
        corrupt[10] = char(corrupt[10] ^ 0x01); // in the epoch's first frame (1074)
        m.feed(view(epochs[0] + "noise between frames" + corrupt + epochs[2]), 0);
        QVERIFY(m.crcErrors() >= 1);
        QVERIFY(m.bytesSkipped() >= 20);
        QCOMPARE(m.messageType(1074, 0)->count + m.messageType(1084, 0)->count,
                 std::uint64_t(5)); // one of the six was corrupted
    }

    void theCorrectionAgeIsSampledIntoABoundedHistory() {
        CorrectionsMonitor m;
        m.sampleAge(0);
        QVERIFY(!m.ageHistory().back().ageMs); // nothing received yet
        rtcm::StationArp arp;
        arp.x = 2845455;
        arp.y = 2160465;
        arp.z = 5265313;
        m.feed(rtcm::encodeStationArp(arp), 500); // a 1005 is no observation
        QVERIFY(!m.correctionAgeMs(600));
        QCOMPARE(m.lastMessageAgeMs(600).value_or(-1), std::int64_t(100));
        const QList<QByteArray> epochs = baseEpochs(1);
        m.feed(view(epochs[0]), 1000);
        for (std::int64_t t = 1000; t < 1000 + 700 * 1000; t += 1000) m.sampleAge(t + 250);
        QCOMPARE(m.ageHistory().size(), std::size_t(CorrectionsMonitor::kHistoryLength));
        QCOMPARE(m.ageHistory().back().ageMs.value_or(-1), std::int64_t(699 * 1000 + 250));
        QCOMPARE(m.ageHistory().front().atMs, std::int64_t(1000 + 100 * 1000 + 250));
        m.reset();
        QVERIFY(m.ageHistory().empty());
        QCOMPARE(m.messages(), std::uint64_t(0));
        QVERIFY(!m.basePosition());
    }

    void messageMeanings_data() {
        QTest::addColumn<int>("number");
        QTest::addColumn<QString>("line");
        QTest::newRow("1004") << 1004 << "1004: GPS L1/L2 observations, extended";
        QTest::newRow("1006") << 1006 << "1006: base position and antenna height";
        QTest::newRow("1033") << 1033 << "1033: receiver and antenna descriptors";
        QTest::newRow("1077") << 1077 << "1077: GPS MSM7";
        QTest::newRow("1097") << 1097 << "1097: Galileo MSM7";
        QTest::newRow("1127") << 1127 << "1127: BeiDou MSM7";
        QTest::newRow("1019") << 1019 << "1019: GPS ephemeris";
        QTest::newRow("4072") << 4072 << "4072: u-blox proprietary";
        QTest::newRow("4050") << 4050 << "4050: proprietary";
        QTest::newRow("1999") << 1999 << "1999: message 1999";
    }
    void messageMeanings() {
        QFETCH(int, number);
        QFETCH(QString, line);
        QCOMPARE(QString::fromStdString(describeRtcmMessage(unsigned(number))), line);
    }
};

QTEST_APPLESS_MAIN(TstCorrectionsMonitor)
#include "tst_corrections_monitor.moc"
