// The simulated NV08C-RTK as a base station, in simulated time: RTCM 3 (#1002, #1010 at RTCMRATE,
// 1005 with BASEID) on the ports PNVGRZA sets to protocol 7, one antenna reference point behind
// BASEXYZ and BASEBLH, BASETH, averaging (MODE 3) and BASENMEA.
#include "builtin/simulators.h"
#include "core/sentence_builder.h"
#include "core/wgs84.h"
#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_messages.h"
#include "sim_output.h"

#include <QTest>

#include <cmath>
#include <map>

using namespace gnss;
using namespace gnss::sim;

namespace {

// The simulator's observer, ellipsoidal height: where the receiver's own fixes are.
const Observer kHere{};
double hereHeight() {
    return kHere.altMsl + kHere.geoidSep;
}

std::unique_ptr<Receiver> makeNvs() {
    SimOptions o;
    return makeReceiver("nvs", o);
}

void command(Receiver &rx, const std::string &body) {
    rx.receive(buildSentence(body) + "\r\n");
}

// BASEBLH for a point `north` metres north of the observer, in radians as the receiver takes it.
std::string blhNorthOfHere(double north) {
    const double lat = kHere.latDeg + north / 111320.0;
    char text[96];
    std::snprintf(text, sizeof text, "%.10f,%.10f,%.4f", wgs84::radians(lat),
                  wgs84::radians(kHere.lonDeg), hereHeight());
    return text;
}

struct Frames {
    std::map<unsigned, int> counts; // per message number
    int count(unsigned number) const {
        auto it = counts.find(number);
        return it == counts.end() ? 0 : it->second;
    }
    std::vector<rtcm::RtcmMessage> messages;
    std::uint64_t bytesSkipped = 0;
};

Frames framesOf(const std::string &bytes) {
    Frames f;
    rtcm::RtcmFramer framer;
    framer.feed(bytes, [&](const rtcm::RtcmFrame &frame) {
        ++f.counts[frame.messageNumber()];
        f.messages.push_back(rtcm::decodeMessage(frame.payload()));
    });
    f.bytesSkipped = framer.stats().bytesSkipped;
    return f;
}

// A base at the observer's own position, its RTCM on COM2.
std::unique_ptr<Receiver> baseOnCom2(const std::string &extra = {}) {
    auto rx = makeNvs();
    rx->advance(40); // a fix first
    command(*rx, "PNVGRZA,2,115200,7");
    command(*rx, "PNVGRTK,MODE,1,BASEID,321,BASEBLH," + blhNorthOfHere(0) + extra);
    rx->takeOutput();
    rx->takeOutput(2);
    return rx;
}

} // namespace

class TstSimNvsBase : public QObject {
    Q_OBJECT
private slots:
    void aRoverSendsNoRtcm() {
        auto rx = makeNvs();
        command(*rx, "PNVGRZA,2,115200,7");
        rx->advance(60);
        QVERIFY(rx->takeOutput(2).empty());
    }

    void aBaseSendsItsObservablesAndPositionOnCom2() {
        auto rx = baseOnCom2();
        rx->advance(20);
        const Frames f = framesOf(rx->takeOutput(2));
        QVERIFY2(f.count(1002) >= 19 && f.count(1002) <= 21,
                 qPrintable(QString::number(f.count(1002))));
        QCOMPARE(f.count(1010), f.count(1002));
        QCOMPARE(f.count(1005), f.count(1002));
        QCOMPARE(f.bytesSkipped, std::uint64_t(0)); // frames only
        for (const rtcm::RtcmMessage &m : f.messages) {
            QCOMPARE(m.station.value_or(0), 321u);
            if (const auto *arp = std::get_if<rtcm::StationArp>(&m.body)) {
                QVERIFY(arp->position);
                QVERIFY(std::abs(arp->position->latDeg - kHere.latDeg) < 1e-7);
                QVERIFY(std::abs(arp->position->height - hereHeight()) < 0.01);
            }
            if (const auto *obs = std::get_if<rtcm::LegacyObservables>(&m.body))
                QVERIFY(obs->satellites.size() >= 4);
        }
        // The host's port keeps its NMEA: no frame there.
        QCOMPARE(framesOf(rx->takeOutput()).messages.size(), std::size_t(0));
    }

    void rtcmRateSetsTheObservablesInterval() {
        auto rx = baseOnCom2(",RTCMRATE,5");
        rx->advance(30);
        const Frames f = framesOf(rx->takeOutput(2));
        QVERIFY2(f.count(1002) >= 5 && f.count(1002) <= 7,
                 qPrintable(QString::number(f.count(1002))));
        QVERIFY(f.count(1005) >= 29); // the station every second
    }

    void onCom1TheRtcmReplacesTheNmea() {
        auto rx = makeNvs();
        rx->advance(40);
        command(*rx, "PNVGRTK,MODE,1,BASEBLH," + blhNorthOfHere(0));
        command(*rx, "PNVGRZA,1,115200,7");
        rx->advance(1);
        rx->takeOutput();
        rx->advance(10);
        const std::string out = rx->takeOutput();
        const Frames f = framesOf(out);
        QVERIFY(f.count(1002) >= 9);
        QVERIFY(out.find("$GPGGA") == std::string::npos && out.find("GGA,") == std::string::npos);
    }

    void xyzAndBlhAreOnePoint() {
        auto rx = makeNvs();
        command(*rx, "PNVGRTK,BASEBLH," + blhNorthOfHere(100));
        rx->takeOutput();
        command(*rx, "PNVGRTK,BASEXYZ");
        rx->advance(0.5);
        const std::string xyzReply = rx->takeOutput();
        const wgs84::Ecef want =
                wgs84::toEcef({kHere.latDeg + 100 / 111320.0, kHere.lonDeg, hereHeight()});
        const auto at = xyzReply.find("BASEXYZ,");
        QVERIFY2(at != std::string::npos, xyzReply.c_str());
        double x = 0, y = 0, z = 0;
        QCOMPARE(std::sscanf(xyzReply.c_str() + at + 8, "%lf,%lf,%lf", &x, &y, &z), 3);
        QVERIFY(std::hypot(x - want.x, y - want.y, z - want.z) < 0.01);
        char expected[64];
        // And the other way round.
        char xyz[96];
        std::snprintf(xyz, sizeof xyz, "%.4f,%.4f,%.4f", want.x, want.y + 50, want.z);
        command(*rx, std::string("PNVGRTK,BASEXYZ,") + xyz);
        rx->takeOutput();
        command(*rx, "PNVGRTK,BASEBLH");
        rx->advance(0.5);
        const std::string blh = rx->takeOutput();
        const auto g = wgs84::toGeodetic({want.x, want.y + 50, want.z});
        std::snprintf(expected, sizeof expected, "%.10f", wgs84::radians(g->lonDeg));
        QVERIFY2(blh.find(expected) != std::string::npos, blh.c_str());
    }

    // BASETH: a set position farther than that from the receiver's own stops its RTCM.
    void pastTheThresholdNoRtcm() {
        auto rx = makeNvs();
        rx->advance(40);
        command(*rx, "PNVGRZA,2,115200,7");
        command(*rx, "PNVGRTK,MODE,1,BASETH,500,BASEBLH," + blhNorthOfHere(800));
        rx->advance(10);
        QCOMPARE(framesOf(rx->takeOutput(2)).messages.size(), std::size_t(0));
        command(*rx, "PNVGRTK,BASETH,1000");
        rx->takeOutput(2);
        rx->advance(5);
        QVERIFY(framesOf(rx->takeOutput(2)).count(1002) >= 4);
    }

    // MODE 3: AVGTIME minutes of its own positions become BASEXYZ/BASEBLH, then RTCM.
    void averagingSetsThePositionThenSends() {
        auto rx = makeNvs();
        rx->advance(40);
        command(*rx, "PNVGRZA,2,115200,7");
        command(*rx, "PNVGRTK,AVGTIME,1,MODE,3");
        rx->advance(50);
        QCOMPARE(framesOf(rx->takeOutput(2)).messages.size(), std::size_t(0));
        rx->advance(90); // the fix after the mode's restart, then a minute of averaging
        const Frames f = framesOf(rx->takeOutput(2));
        QVERIFY(f.count(1002) >= 10);
        const rtcm::StationArp *arp = nullptr;
        for (const auto &m : f.messages)
            if (const auto *a = std::get_if<rtcm::StationArp>(&m.body)) arp = a;
        QVERIFY(arp && arp->position);
        const double north = (arp->position->latDeg - kHere.latDeg) * 111320.0;
        QVERIFY2(std::abs(north) < 3 && std::abs(arp->position->height - hereHeight()) < 5,
                 qPrintable(QString("%1 m north, %2 m").arg(north).arg(arp->position->height)));
    }

    // BASENMEA 0: the NMEA position is the base's; 1: the receiver's own.
    void baseNmeaChoosesTheReportedPosition() {
        auto rx = baseOnCom2();
        command(*rx, "PNVGRTK,BASEBLH," + blhNorthOfHere(200) + ",BASENMEA,0");
        rx->advance(3);
        auto lat = [](const std::string &out) {
            for (const auto &l : test::summarize(out, "nvs").lines)
                if (l.line.find("GGA,") != std::string::npos) {
                    const auto f = l.line.find(',', l.line.find(',') + 1) + 1;
                    const double ddmm = std::stod(l.line.substr(f, 10));
                    return std::floor(ddmm / 100) + std::fmod(ddmm, 100) / 60;
                }
            return 0.0;
        };
        rx->takeOutput();
        rx->advance(2);
        QVERIFY(std::abs((lat(rx->takeOutput()) - kHere.latDeg) * 111320.0 - 200) < 0.5);
        command(*rx, "PNVGRTK,BASENMEA,1");
        rx->advance(2);
        rx->takeOutput();
        rx->advance(2);
        QVERIFY(std::abs((lat(rx->takeOutput()) - kHere.latDeg) * 111320.0) < 20);
    }
};

QTEST_GUILESS_MAIN(TstSimNvsBase)
#include "tst_sim_nvs_base.moc"
