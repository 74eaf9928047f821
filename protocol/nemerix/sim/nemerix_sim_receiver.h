#pragma once
// NemerixReceiver: a VT002 module (Nemerix NemeriX NJ1006/NJ1030 chipset) as
// vt002-nemerix-nmea.txt describes it: GPS only, NMEA 0183 3.0 (no system or signal ids), at
// most 12 satellites in GSV, checksums always sent (the spec makes them optional on input).
//
// Settings: a SettingsStore of the nemerix schema (its defaults: 9600 baud 8N1; GGA, RMC, VTG
// every second, GSA and GSV every 3 s; sequence GGA GSA GSV RMC VTG), with the values the schema
// leaves open seeded. Every command is applied to it as the dialect reads it (extractSettings);
// what stays here is what a command does beyond its settings. The spec documents no
// acknowledgement, so only PNMRX600 and PNMRX603 are answered, as the dialect's reply rules say:
//   PNMRX100 port: the speed changes once read;
//   PNMRX101/104 navigation init: a position restarts the receiver, a fix procedure code
//     (4 cold) is kept for PNMRX111 without parameter, 8 is a factory reset;
//   PNMRX103 a rate for a message outside the sequence appends it to the sequence;
//   PNMRX107 PNMRX300-304 modes (1 now, 2 on change, 3 both; the reports are sent a few a
//     second, interleaved with the NMEA output, as the spec advises);
//   PNMRX110 masks (time zone in ZDA, SNR and elevation masks in the fix);
//   PNMRX111 resets (none: per fix procedure; bit field; FACTORY/COLD/WARM/HOT);
//   PNMRX113 stops fixes and data extraction until a reset;
//   PNMRX300 almanac upload; PNMRX600 version; PNMRX601 ISP mode (silent until power cycle);
//   PNMRX603 the five settings reports (messages 0..4) from the store.
// Every PNMRX sentence it sends is built by the nemerix encoders (nemerix_commands.h).
// The VT002 has no "save" command: a power cycle returns to the factory settings.
#include "nemerix/nemerix_messages.h"
#include "sim/dialect_receiver.h"
#include "sim/standard_output.h"

#include <deque>
#include <set>
#include <string>

namespace gnss::sim {

// Its settings (settings()) by the schema's keys: "rate.GGA", "fix.minSnr", "serial.baud".
class NemerixReceiver : public DialectReceiver {
public:
    explicit NemerixReceiver(const SimOptions &options = {});

    bool coreStopped() const { return coreStopped_; }
    bool ispMode() const { return isp_; }
    int uploadedAlmanacs() const { return static_cast<int>(uploaded_.size()); }

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind kind) override;
    UseMask useMask() const override;
    FixKind fixAfter(double seconds) const override;

private:
    std::vector<std::string> sentencesOf(std::string_view id, const SkySnapshot &snap) const;
    std::vector<std::string> settingsReports() const;
    // Queues the reports of PNMRX30x (index 0..4 of nemerix::kNavDataMessageIds) for output.
    void queueReport(std::size_t index, const SkySnapshot &snap);
    void queue(const EncodeResult &built);
    void reportModesChanged(const nemerix::RateList &modes);
    void keepRatedInSequence(const nemerix::RateList &rates);
    void factorySettings();
    void softwareReset(std::optional<int> bits, std::string_view named);
    // The output sequence's messages (PNMRX108 order), and the messages in output order: the
    // sequence, then any other with a rate.
    std::vector<std::string_view> sequence() const;
    std::vector<std::string_view> outputOrder() const;
    int reportMode(std::size_t index) const;

    int fixProcedure_ = 0; // PNMRX101's code for a PNMRX111 without parameter: 0 hot, 4 cold
    bool coreStopped_ = false;
    bool isp_ = false;
    std::set<int> uploaded_;        // PNMRX300 uploads (SV ids)
    std::set<int> ephemerisSent_;   // "on change": SVs whose ephemeris was reported
    bool dataReported_ = false;     // "on change" of 300/302/303/304: once data are collected
    std::deque<std::string> queue_; // PNMRX30x messages waiting for the line
    std::int64_t second_ = 0;
};

} // namespace gnss::sim

namespace gnss::nemerix {
// The family's simulated receiver (its row in a sim::SimulatorTable).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::nemerix
