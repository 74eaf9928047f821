#pragma once
// NvsReceiver: an NVS NV08C-RTK-A (the heading variant of the NV08C-RTK, a superset: it also
// sends HDT, PNVGBLS, PNVGSDH) as nvs-nv08c-rtk-nmea-v1.6.txt describes it.
//
// Defaults: 115200 baud, PVT rate 5 Hz, RTK rover (MODE 2) with a simulated base 4.8 km away
// (station 0002) whose corrections arrive from the first fix: autonomous → float after 5 s →
// fixed after 15 s. The spec gives no default output list; the simulator sends GGA, GSA, RMC,
// VTG every epoch and GSV, ZDA, PNVGBSS once a second, and PNVGTST once at start (4.7).
// Commands (read with the NVS decoders, answered with the NVS encoders):
//   PNVGVER, $--GPQ,<address>, PNVGNME (echo, then switch), PNVGRST (no reply, restarts),
//   PNVGRZA (reply, then the baud changes), PNVGRZB (no reply, output list), PNVGCFG W/E/R,
//   PNVGPPS, PNVGRTK (reply names every parameter asked; an out-of-range value is not taken and
//   the reply carries the value in force), PNVGIDL MODE/ADD/REMOVE/CLEAR/SHOW.
// PNVGCFG,W saves to the simulated flash; a power cycle (Receiver::powerCycle(), SIGHUP to
// gnss-sim) and PNVGCFG,R restore from it; PNVGRST keeps the settings in force (spec table 4.3).
#include "sim/receiver.h"
#include "sim/standard_output.h"

#include "nvs/nvs_actions.h"
#include "nvs/nvs_messages.h"
#include "rtcm/rtcm_framer.h"

#include <map>

namespace gnss::sim {

class NvsReceiver : public Receiver {
public:
    explicit NvsReceiver(const SimOptions &options = {});
    static constexpr int kDefaultBaud = nvs::kDefaultBaud;

    struct Station {
        int id = 0;
        double icb = 0;
    };
    struct Port {
        int baud = kDefaultBaud;
        int protocol = 1; // 0 off, 1 NMEA, 7 RTCM
        std::vector<nvs::RzbEntry> output;
    };
    // Everything PNVGCFG saves (spec 4.8), plus PNVGNME's settings.
    struct Settings {
        std::map<std::string, std::string, std::less<>> rtk; // Table 4 name → value(s) as sent
        int timeDecimals = 2, positionDecimals = 7, talkerMode = 0;
        std::map<int, Port> ports; // 1 COM1, 2 COM2, 3 USB
        char ppsType = 'P', ppsMode = 'S', ppsReference = 'U', ppsValidity = 'D';
        int ppsAdjust = 1, ppsDuration = 1000, ppsCableDelay = 0;
        int idlMode = 0;
        std::vector<Station> stations;
    };

    const Settings &settings() const { return current_; }
    const Settings &savedSettings() const { return saved_; }
    std::string rtkValue(std::string_view name) const;
    double epochInterval() const override;

    static constexpr int kCurrentPort = 1; // the simulated host is on COM1

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind kind) override;
    UseMask useMask() const override;
    FixKind fixAfter(double seconds) const override;
    void onHostBytes(std::string_view bytes) override;

private:
    Settings defaults() const;
    int mode() const;
    StandardStyle style() const;
    // Sentences of one output address for the current epoch ("GGA", "PNVGBSS", "BSS", ...).
    std::vector<std::string> sentencesOf(std::string_view address, const SkySnapshot &snap);
    std::string timeField() const;
    std::string proprietary(std::string_view body) const;

    void handleRtk(const Sentence &s, const nvs::Rtk &m);
    void handleRzb(const nvs::Rzb &m);
    void handleRza(const Sentence &s, const nvs::Rza &m);
    void handleNme(const Sentence &s, const nvs::Nme &m);
    void handleCfg(const Sentence &s, const nvs::Cfg &m);
    void handlePps(const Sentence &s, const nvs::Pps &m);
    void handleIdl(const Sentence &s, const nvs::Idl &m);

    Settings current_, saved_;
    std::int64_t epochIndex_ = 0;
    bool sendTestResults_ = true;
    // Base station link (RTK rover).
    double baseNorth_ = 4604.566, baseEast_ = -1242.064, baseUp_ = -27.096; // base → rover ENU
    std::int64_t rtcmTotal_ = 0, rtcmErrors_ = 0;
    double lastRtcm_ = -1, nextRtcm_ = 0;
    double flowSince_ = -1;            // corrections from the host arrive without a break since
    rtcm::RtcmFramer hostRtcm_;        // the host's bytes: RTCM 3 frames among the commands
    double correctionAgeLimit() const; // RTCMAGE, seconds
    // Time mark events.
    std::int64_t markCounter_ = 0;
    double nextMark_ = 0.7, lastMark_ = -1;
    SkySnapshot markSnap_;
    bool markPending_ = false;
    double heading_ = 40.61; // ANT1→ANT2 course, degrees
};

} // namespace gnss::sim

namespace gnss::nvs {
// The record's simulator (Dialect::makeSimulator).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::nvs
