#pragma once
// GeoStarReceiver: a GeoStar GeoS-5M (GPS, GLONASS, Galileo, SBAS) as
// geostar-geos5-nmea-v4.0.ru.txt describes it.
//
// Defaults (the spec names none; taken from its one NQUERY example and the dialect's baud):
// 115200 baud, 1 Hz, NMEA v2.x, GGA and GSA at the output rate, GSV, ZDA and DTM every second,
// GNSS mode MIX (GLONASS+GPS+Galileo), SBAS corrections allowed, WGS-84, elevation mask 5 deg.
// RQUERY and NQUERY are sent once after power-on, and once a second while every standard
// message is off (3.11, 3.12).
//
// Commands (section 4, read with the geostar decoder, the table of geostar_commands.cpp):
// only RQUERY and NQUERY are answered; every other command acts silently (the spec names no
// acknowledgement), its effect visible in the output, in the NQUERY reply or in the RQUERY words.
// BDRxxx switches the port speed once the command is read; SWPROT leaves NMEA (the port falls
// silent: the binary protocol is not simulated) until a power cycle.
// SAVEFL writes the almanacs and the settings in force to the simulated flash (status bit 30
// set for a second); a power cycle (powerCycle(), SIGHUP) reloads the settings from flash
// (status bit 3) with the almanacs available at once. Without SAVEFL a power cycle returns to
// the defaults.
// NMEAV2 / NMEAV4 switch the numbering (3.4, 3.5): v2.x: GSV all under GP with three-digit ids
// (Galileo 101-136), GSA per system (GP/GL/GA); v4.10: GN talkers, GSA with the system id,
// GSV per system with the signal id (Galileo 7), GNS with per-system subsidiary sentences.
#include "geostar/geostar_actions.h"
#include "sim/receiver.h"
#include "sim/standard_output.h"

#include <array>
#include <cstdint>
#include <string>

namespace gnss::sim {

class GeoStarReceiver : public Receiver {
public:
    explicit GeoStarReceiver(const SimOptions &options = {});
    static constexpr int kDefaultBaud = geostar::kDefaultBaud;

    // Output messages in NQUERY order (3.12; the 7th position is unknown and always 0).
    static constexpr std::array<std::string_view, 10> kOutputs = {
            "GGA", "GLL", "GSA", "GSV", "RMC", "VTG", "", "ZDA", "DTM", "RLM"};

    struct Settings {
        // NQUERY per-message codes: '0' off, '1' every s, '2' every 2 s, '3' every 20 s,
        // 'R' at the output rate.
        std::array<char, 10> codes{};
        int rateHz = 1;
        int nmeaVersion = 2;
        bool powerSaving = false;
        int elevationMask = 5;
        std::string datum = "W84"; // W84 / P90
        std::string gnss = "MIX";  // GPS / GLN / MIX
        int baud = kDefaultBaud;
        int stopBits = 1;
        bool operator==(const Settings &) const = default;
    };

    const Settings &settings() const { return current_; }
    double epochInterval() const override { return 1.0 / current_.rateHz; }

    // The RQUERY words (tables 7, 8, 9) of the current state.
    std::uint32_t statusWord() const;
    std::uint32_t configRegister1() const;
    std::uint32_t configRegister2() const;
    std::string rqueryReply() const;
    std::string nqueryReply() const;
    bool binaryProtocol() const { return binary_; }

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind kind) override;
    UseMask useMask() const override;
    FixKind fixAfter(double seconds) const override;

private:
    static Settings defaults();
    bool allStandardOff() const;
    void apply(std::string_view settingKey, std::string_view value);
    std::vector<std::string> sentencesOf(std::string_view name, const SkySnapshot &snap) const;

    // Output builders (numbering and talkers by NMEA version).
    std::string talker() const; // v2: GP; v4: GN / GP / GL by GNSS mode
    std::vector<std::string> gsa(const SkySnapshot &snap) const;
    std::vector<std::string> gsv(const SkySnapshot &snap) const;
    std::vector<std::string> gns(const SkySnapshot &snap) const;
    std::string gga(const SkySnapshot &snap) const;
    std::string dtm() const;
    std::string rlm() const;

    Settings current_, flash_;
    bool flashWritten_ = false;    // SAVEFL done at least once
    bool loadedFromFlash_ = false; // settings came from flash at the last power-on
    bool almanacInFlash_ = false;
    double almanacSince_ = 0;      // almanacs complete from this time (tracking + 30 s)
    bool almanacValid_ = false;    // kept over resets except CSTART
    double flashWriteUntil_ = -1;  // status bit 30
    bool binary_ = false;          // SWPROT: NMEA off until power cycle
    bool hotStart_ = false;        // status bit 15
    bool validSinceStart_ = false; // status bit 18
    bool announce_ = true;         // RQUERY + NQUERY after power-on
    std::int64_t epochIndex_ = 0;
    double lastAllOffReport_ = -1;
};

} // namespace gnss::sim

namespace gnss::geostar {
// The record's simulator (Dialect::makeSimulator).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::geostar
