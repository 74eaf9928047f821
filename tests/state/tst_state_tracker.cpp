// StateTracker: vendor messages become vendor-neutral receiver state (RTK, attitude, time marks,
// identity, reports) through each dialect's updateState hook.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "state/state_tracker.h"
#include "track_state.h"

#include <QTest>

using namespace gnss;

namespace {

ReceiverState track(const std::vector<std::string> &lines, int *epochs = nullptr) {
    return test::trackState(lines, epochs);
}

} // namespace

class TstStateTracker : public QObject {
    Q_OBJECT
private slots:
    void nvsRtkSentencesFillTheRtkState() {
        int epochs = 0;
        const ReceiverState st =
                track({buildSentence("GPGGA,145505.20,4724.5118287,N,00937.6956032,E,4,17,0.7,403."
                                     "995,M,47.848,M,2.2,0002"),
                       buildSentence("PNVGBSS,1200,3,1197,4769.223,1.2"),
                       "$PNVGBRS,091244.60,4604.566,-1242.064,-27.096,4769.223,344.90,-0.33,R*1A",
                       "$PNVGBLS,145505.20,0.437,0.374,-0.040,0.576,40.61,-4.01,R*1A",
                       "$PNVGSDP,151337.40,0.005,0.004,0.009,R*38",
                       "$PNVGSDV,151337.40,0.087,0.077,0.118,R*31", "$PNVGSDH,151337.40,0.978,R*2E",
                       "$PNVGDOP,121707.80,1.06,0.94,0.59,0.73,0.50,0.41,0.42,R*14",
                       "$PNVGVOG,140327.80,1.437,5.374,-0.041,R*08",
                       "$PNVGIMU,145505.20,0.42,0.37,21.84,0.065,0.064,-0.201*7C"},
                      &epochs);
        QCOMPARE(epochs, 1);
        QCOMPARE(int(st.epoch.fix), int(FixType::RtkFixed));
        QVERIFY(st.rtk.seen);
        QCOMPARE(*st.rtk.rtcmTotal, std::int64_t(1200));
        QCOMPARE(*st.rtk.correctionAge, 1.2);
        QCOMPARE(*st.rtk.baseToRover.length, 4769.223);
        QCOMPARE(*st.rtk.antennas.course, 40.61);
        QCOMPARE(*st.rtk.heading, 40.61);
        QCOMPARE(*st.rtk.sdHeight, 0.009);
        QCOMPARE(*st.rtk.sdHeading, 0.978);
        QCOMPARE(*st.rtk.edop, 0.42);
        QCOMPARE(*st.rtk.velNorth, 1.437);
        QCOMPARE(*st.rtk.mode, 'R');
        QVERIFY(st.attitude.seen);
        QCOMPARE(*st.attitude.yaw, 21.84);
        QCOMPARE(*st.attitude.accDown, -0.201);
    }

    void nvsTimeMarkSentencesMakeOneEvent() {
        const ReceiverState st =
                track({"$PNVGTME,128,40327.564756284*49", "$PNVGTMU,128,081248.547824228*61",
                       "$PNVGTMC,145505.28,4724.5118287,N,00937.6956032,E,4,17,0.7,403.995,M,"
                       "47.848,M,2.2,0002*4D",
                       buildSentence("PNVGTME,129,40328.5")});
        QCOMPARE(st.timeMarks.size(), std::size_t(2));
        const TimeMarkEvent &e = st.timeMarks.front();
        QCOMPARE(*e.counter, std::int64_t(128));
        QCOMPARE(*e.towSeconds, 40327.564756284);
        QCOMPARE(QString::fromStdString(e.utc->toString()), QString("08:12:48.547824228"));
        QCOMPARE(*e.altMsl, 403.995);
        QCOMPARE(*st.timeMarks.back().counter, std::int64_t(129));
    }

    void identityAndReportsFromEachVendor() {
        ReceiverState st = track({buildSentence("PNVGVER,NVS,RTK,0029,CSM24,0101")});
        QCOMPARE(QString::fromStdString(st.identity.model), QString("NV08C-RTK"));
        QCOMPARE(QString::fromStdString(st.identity.firmware), QString("0029"));
        QCOMPARE(QString::fromStdString(st.identity.hardware), QString("CSM24 0101"));
        QVERIFY(st.reports.count("Version"));
        // Device id RTA: the NV08C-RTK-A (the heading receiver), by its product's name.
        st = track({buildSentence("PNVGVER,NVS,RTA,0029,CSM24,0101")});
        QCOMPARE(QString::fromStdString(st.identity.model), QString("NV08C-RTK-A"));

        st = track({"$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C"});
        QCOMPARE(QString::fromStdString(st.identity.vendor), QString("GeoStar"));
        QCOMPARE(QString::fromStdString(st.identity.model), QString("GeoS-5M"));
        QCOMPARE(QString::fromStdString(st.identity.firmware), QString("5.102"));
        QVERIFY(st.jamming.has_value());
        QVERIFY(!*st.jamming);
        QCOMPARE(st.reports.size(), std::size_t(1));
        QVERIFY(st.reports.begin()->second.find("\"antenna\"") != std::string::npos);

        st = track({buildSentence("PNMRX600,VT002,1.23,NMX")});
        QCOMPARE(QString::fromStdString(st.identity.vendor), QString("Nemerix"));
        QCOMPARE(QString::fromStdString(st.identity.model), QString("VT002"));
        QCOMPARE(QString::fromStdString(st.identity.firmware), QString("1.23 NMX"));
    }

    void standardHeadingAndDeviationsToo() {
        const ReceiverState st =
                track({buildSentence("GPHDT,274.07,T"),
                       buildSentence("GPGST,172814.0,0.006,0.023,0.020,273.6,0.023,0.020,0.031")});
        QCOMPARE(*st.rtk.heading, 274.07);
        QCOMPARE(*st.rtk.sdHeight, 0.031);
    }
};

QTEST_APPLESS_MAIN(TstStateTracker)
#include "tst_state_tracker.moc"
