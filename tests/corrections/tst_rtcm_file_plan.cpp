// The playback plan of a recorded RTCM file: one group per MSM epoch (GPS and GLONASS of an
// epoch together), 1 Hz per 1005 without MSMs, gaps capped, clocks going backwards tolerated,
// and every byte of the file in exactly one group, in order.
#include "corrections/rtcm_file_plan.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_fixtures.h"

#include <QTest>

using namespace gnss;
using namespace gnss::corrections;
using namespace corrections_test;

namespace {

// The groups cover the file whole, in order, without overlap.
bool coversTheFile(const PlaybackPlan &p, std::size_t size) {
    std::size_t pos = 0;
    for (const PlaybackGroup &g : p.groups) {
        if (g.begin != pos || g.end < g.begin) return false;
        pos = g.end;
    }
    return pos == size;
}

QByteArray gpsMsm(std::uint32_t towMs) {
    rtcm::MsmHeader h;
    h.system = rtcm::System::Gps;
    h.msmType = 4;
    h.epochMs = towMs;
    h.satelliteMask = 0xF000000000000000ull;
    h.signalMask = 0x40000000u;
    h.cellMask = 0xF;
    return QByteArray::fromStdString(rtcm::encodeMsm(h));
}

QByteArray station() {
    rtcm::StationArp a;
    a.x = 2845455;
    a.y = 2160465;
    a.z = 5265313;
    return QByteArray::fromStdString(rtcm::encodeStationArp(a));
}

} // namespace

class TstRtcmFilePlan : public QObject {
    Q_OBJECT
private slots:
    void msmEpochsAreGroupsOneSecondApart() {
        QByteArray file;
        for (const QByteArray &e : baseEpochs(6)) file += e;
        const PlaybackPlan p = planPlayback(view(file));
        QCOMPARE(p.timing, PlaybackPlan::Timing::Msm);
        QCOMPARE(int(p.groups.size()), 6);
        for (int i = 0; i < 6; ++i) {
            QCOMPARE(p.groups[std::size_t(i)].atMs, std::int64_t(i * 1000));
            // MSM4 GPS + MSM4 GLONASS + 1005 (+ 1230 at the first), though the GLONASS clock is
            // hours from the GPS one.
            QCOMPARE(int(p.groups[std::size_t(i)].frames), i == 0 ? 4 : 3);
        }
        QVERIFY(coversTheFile(p, std::size_t(file.size())));
        QCOMPARE(p.durationMs(), std::int64_t(5000));
    }

    void withoutMsmsEach1005IsASecond() {
        const QByteArray eph = QByteArray::fromStdString(rtcm::encodeGlonassBiases({}));
        const QByteArray file = station() + eph + station() + eph + eph + station();
        const PlaybackPlan p = planPlayback(view(file));
        QCOMPARE(p.timing, PlaybackPlan::Timing::StationMessages);
        QCOMPARE(int(p.groups.size()), 3);
        QCOMPARE(p.groups[1].atMs, std::int64_t(1000));
        QCOMPARE(p.groups[2].atMs, std::int64_t(2000));
        QCOMPARE(int(p.groups[1].frames), 3);
        QVERIFY(coversTheFile(p, std::size_t(file.size())));
    }

    void neitherMsmNor1005IsSentAtOnce() {
        const QByteArray b = QByteArray::fromStdString(rtcm::encodeGlonassBiases({}));
        const PlaybackPlan p = planPlayback(view(b + b + b));
        QCOMPARE(p.timing, PlaybackPlan::Timing::AllAtOnce);
        QCOMPARE(int(p.groups.size()), 1);
        QCOMPARE(int(p.frames), 3);
    }

    void noiseTravelsWithTheFramesAroundIt() {
        const QByteArray file = "junk" + gpsMsm(1000) + "between" + gpsMsm(2000) + "tail";
        const PlaybackPlan p = planPlayback(view(file));
        QCOMPARE(int(p.groups.size()), 2);
        QCOMPARE(p.groups[0].begin, std::size_t(0));
        QVERIFY(coversTheFile(p, std::size_t(file.size())));
        QCOMPARE(file.mid(qsizetype(p.groups[1].begin), 7), QByteArray("between"));
    }

    void gapsAreCappedAndBackwardClocksTolerated_data() {
        QTest::addColumn<QList<int>>("towSeconds");
        QTest::addColumn<QList<int>>("atMs");
        QTest::newRow("steady") << QList<int>{100, 101, 102} << QList<int>{0, 1000, 2000};
        QTest::newRow("a two-hour gap plays as a minute")
                << QList<int>{100, 7300, 7301} << QList<int>{0, 60000, 61000};
        QTest::newRow("two files joined: the clock goes back")
                << QList<int>{5000, 5001, 100, 101} << QList<int>{0, 1000, 2000, 3000};
        QTest::newRow("across the week's end")
                << QList<int>{604799, 0, 1} << QList<int>{0, 1000, 2000};
        QTest::newRow("5 Hz") << QList<int>{-1} << QList<int>{0, 200, 400, 600, 800};
    }
    void gapsAreCappedAndBackwardClocksTolerated() {
        QFETCH(QList<int>, towSeconds);
        QFETCH(QList<int>, atMs);
        QByteArray file;
        if (towSeconds == QList<int>{-1}) {
            for (int i = 0; i < 5; ++i) file += gpsMsm(std::uint32_t(1000000 + i * 200));
        } else {
            for (int s : towSeconds) file += gpsMsm(std::uint32_t(s) * 1000u);
        }
        const PlaybackPlan p = planPlayback(view(file));
        QList<int> got;
        for (const PlaybackGroup &g : p.groups) got.append(int(g.atMs));
        QCOMPARE(got, atMs);
    }

    void noFramesMeansNothingToPlay() {
        const PlaybackPlan p = planPlayback("no rtcm here at all");
        QCOMPARE(int(p.frames), 0);
        QVERIFY(coversTheFile(p, 19));
        QVERIFY(planPlayback({}).groups.empty());
    }
};

QTEST_APPLESS_MAIN(TstRtcmFilePlan)
#include "tst_rtcm_file_plan.moc"
