#pragma once
// NvsReceiver: an NVS NV08C-RTK-A (the heading variant of the NV08C-RTK, a superset: it also
// sends HDT, PNVGBLS, PNVGSDH) as nvs-nv08c-rtk-nmea-v1.6.txt describes it.
//
// Its settings are the schema's (a SettingsStore seeded from its defaults: 115200 baud, PVT rate
// 5 Hz, RTK rover), with a simulated base 4.8 km away (station 0002) whose corrections arrive
// from the first fix: autonomous → float after 5 s → fixed after 15 s. The spec gives no default
// output list; the simulator sends GGA, GSA, RMC, VTG every epoch and GSV, ZDA, PNVGBSS once a
// second, and PNVGTST once at start (4.7). Everything it sends is built by the NVS encoders.
// Commands (read with the NVS decoders, applied to the store through the dialect's reading):
//   PNVGVER, $--GPQ,<address>, PNVGNME (echo, then switch), PNVGRST (no reply, restarts),
//   PNVGRZA (reply, then the baud changes), PNVGRZB (no reply, output list), PNVGCFG W/E/R,
//   PNVGPPS, PNVGRTK (reply names every parameter asked; an out-of-range value is not taken and
//   the reply carries the value in force), PNVGIDL MODE/ADD/REMOVE/CLEAR/SHOW.
// PNVGCFG,W saves to the simulated flash; a power cycle (Receiver::powerCycle(), SIGHUP to
// gnss-sim) and PNVGCFG,R restore from it; PNVGRST keeps the settings in force (spec table 4.3).
//
// As a base (MODE 1, or 3 once AVGTIME minutes of its own positions are averaged into BASEXYZ)
// it sends RTCM 3 on every port PNVGRZA set to protocol 7: #1002 and #1010 every RTCMRATE
// seconds (once a second for 0, "as the PVT rate"), the station (1005) with BASEID every second.
// BASEXYZ and BASEBLH are one antenna reference point: writing either sets both. Past BASETH
// metres between that point and its own position it sends no RTCM; with BASENMEA 0 its NMEA
// reports the base position. The host is on COM1; COM2's output is takeOutput(2).
#include "sim/dialect_receiver.h"
#include "sim/standard_output.h"

#include "core/wgs84.h"
#include "nvs/nvs_messages.h"
#include "nvs/nvs_schema.h"
#include "rtcm/rtcm_framer.h"
#include "sim/rtcm_base_station.h"

#include <memory>

#include <optional>

namespace gnss::sim {

// Its settings (settings()): everything PNVGCFG saves (spec 4.8) and PNVGNME's settings, under
// the schema's keys ("rtk.PVTRATE", "nmea.time_decimals", "port.COM1.baud", "output.COM1",
// "pps.type", "idl.stations", ...).
class NvsReceiver : public DialectReceiver {
public:
    explicit NvsReceiver(const SimOptions &options = {});

    static constexpr int kCurrentPort = 1; // the simulated host is on COM1
    static constexpr int kBaseStation = 2; // the simulated base's id (PNVGRTK BASEID default)

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind kind) override;
    UseMask useMask() const override;
    FixKind fixAfter(double seconds) const override;
    void onHostBytes(std::string_view bytes) override;

private:
    int mode() const;
    // Output (nvs_sim_output.cpp): the sentences of one address for the current epoch ("GGA",
    // "PNVGBSS", "BSS", ...), in the style PNVGNME sets.
    std::vector<std::string> sentencesOf(std::string_view address, const SkySnapshot &snap);
    StandardStyle style() const;
    std::optional<TimeOfDay> now() const; // the epoch's UTC at PNVGNME's time decimals
    // The address an output-list entry or a query names ("RMC"; "BSS" or "PNVGBSS" → "PNVGBSS"),
    // empty when the receiver sends no such sentence.
    std::string canonical(std::string_view address) const;
    // The port a command names (0 or none: the host's), nullopt when there is no such port.
    static std::optional<int> portOf(std::optional<int> port);
    std::vector<nvs::RzbEntry> outputList(int port) const;
    std::vector<nvs::Station> stations() const;
    // The reply that reports the settings written together with `key` (PNVGNME, PNVGPPS, ...).
    std::string reportOf(std::string_view key) const;

    void handleRtk(const Sentence &s, const nvs::Rtk &m);
    void handleRzb(const nvs::Rzb &m);
    void handleRza(const Sentence &s, const nvs::Rza &m);
    void handleNme(const Sentence &s, const nvs::Nme &m);
    void handleCfg(const Sentence &s, const nvs::Cfg &m);
    void handlePps(const Sentence &s, const nvs::Pps &m);
    void handleIdl(const Sentence &s, const nvs::Idl &m);

    // Base station (MODE 1 and 3).
    bool isBase() const { return mode() == 1 || mode() == 3; }
    void baseEpoch(const SkySnapshot &snap);
    // BASEXYZ or BASEBLH was written: the other follows (one antenna reference point).
    void syncBasePosition(bool fromXyz);
    void setBasePosition(const wgs84::Geodetic &g);
    std::optional<wgs84::Geodetic> basePosition() const;
    // The epoch as NMEA reports it: at the base position with BASENMEA 0 in base mode.
    SkySnapshot reported(const SkySnapshot &snap) const;
    std::unique_ptr<RtcmBaseStation> baseTx_;
    double averagingSince_ = -1; // MODE 3: averaging since (simulated time), -1 when done
    double averageSum_[3] = {0, 0, 0};
    long long averaged_ = 0;
    bool beyondThreshold_ = false; // BASETH exceeded: no RTCM

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
// The family's simulated receiver (its row in a sim::SimulatorTable).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::nvs
