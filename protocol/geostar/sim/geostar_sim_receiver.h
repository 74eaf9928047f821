#pragma once
// GeoStarReceiver: a GeoStar GeoS-5M (GPS, GLONASS, Galileo, SBAS) as
// geostar-geos5-nmea-v4.0.ru.txt describes it.
//
// Settings: a sim::SettingsStore of the dialect's schema, keyed as the schema names them
// (output.GGA ... output.NMEAV, output.RATE, power.PSM, nav.ELEV, nav.DAT, nav.NVS, port.BDR,
// port.STOP). The spec names no factory defaults, so the schema has none: the receiver starts with
// the outputs and rate of the spec's one NQUERY example (1 Hz, NMEA v2.x, GGA and GSA at the
// output rate, GSV, ZDA and DTM every second), GNSS mode MIX (GLONASS+GPS+Galileo), SBAS
// corrections allowed, WGS-84, elevation mask 5 deg, power saving off, one stop bit, and the
// dialect's default speed (or SimOptions::baud).
// RQUERY and NQUERY are sent once after power-on, and once a second while every standard
// message is off (3.11, 3.12); both are built with the dialect's encoders (geostar_encoders.h)
// from the store (reportSettings) and the engine's state (the status word's fields).
//
// Commands (section 4, read with the geostar decoder, the table of geostar_commands.cpp): a set
// command is applied to the store as the dialect reads it (extractSettings); only RQUERY and
// NQUERY are answered; every other command acts silently (the spec names no acknowledgement),
// its effect visible in the output, in the NQUERY reply or in the RQUERY words.
// BDRxxx switches the port speed once the command is read; SWPROT leaves NMEA (the port falls
// silent: the binary protocol is not simulated) until a power cycle.
// SAVEFL writes the almanacs and the settings in force to the simulated flash (status bit 30
// set for a second); a power cycle (powerCycle(), SIGHUP) reloads the settings from flash
// (status bit 3) with the almanacs available at once. Without SAVEFL a power cycle returns to
// the power-on settings.
// NMEAV2 / NMEAV4 switch the numbering (3.4, 3.5): v2.x: GSV all under GP with three-digit ids
// (Galileo 101-136), GSA per system (GP/GL/GA); v4.10: GN talkers, GSA with the system id,
// GSV per system with the signal id (Galileo 7), GNS with per-system subsidiary sentences.
#include "geostar/geostar_messages.h"
#include "sim/dialect_receiver.h"
#include "sim/standard_output.h"

#include <cstdint>
#include <string>

namespace gnss::sim {

class GeoStarReceiver : public DialectReceiver {
public:
    explicit GeoStarReceiver(const SimOptions &options = {});

    // The RQUERY and NQUERY replies (3.11, 3.12) of the current state.
    geostar::Rquery rquery() const;
    geostar::Nquery nquery() const;
    bool binaryProtocol() const { return binary_; }

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind kind) override;
    UseMask useMask() const override;
    FixKind fixAfter(double seconds) const override;

private:
    int nmeaVersion() const { return static_cast<int>(store_.integer("output.NMEAV", 2)); }
    const std::string &gnssMode() const { return store_.value("nav.NVS"); }
    void sendReports(); // RQUERY and NQUERY unasked
    std::vector<std::string> sentencesOf(std::string_view name, const SkySnapshot &snap) const;

    // Output builders (numbering and talkers by NMEA version).
    std::string talker() const; // v2: GP; v4: GN / GP / GL by GNSS mode
    std::vector<std::string> gsa(const SkySnapshot &snap) const;
    std::vector<std::string> gsv(const SkySnapshot &snap) const;
    std::vector<std::string> gns(const SkySnapshot &snap) const;
    std::string gga(const SkySnapshot &snap) const;
    std::string dtm() const;
    std::string rlm() const;

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
    double lastAllOffReport_ = -1;
};

} // namespace gnss::sim

namespace gnss::geostar {
// The family's simulated receiver (its row in a sim::SimulatorTable).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::geostar
