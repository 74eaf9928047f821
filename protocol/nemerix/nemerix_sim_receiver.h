#pragma once
// NemerixReceiver: a VT002 module (Nemerix NemeriX NJ1006/NJ1030 chipset) as
// vt002-nemerix-nmea.txt describes it: GPS only, NMEA 0183 3.0 (no system or signal ids), at
// most 12 satellites in GSV, checksums always sent (the spec makes them optional on input).
//
// Defaults (2.1.8 and the schema's defaults): 9600 baud 8N1; GGA, RMC, VTG every second, GSA
// and GSV every 3 s; sequence GGA GSA GSV RMC VTG.
// Commands (read with the nemerix decoders; the spec documents no acknowledgement, so only
// PNMRX600 and PNMRX603 are answered, as the dialect's reply rules say):
//   PNMRX100 port (protocol, baud 1200..57600, parity): the speed changes once read;
//   PNMRX101/104 navigation init: a position restarts the receiver, a fix procedure code
//     (4 cold) is kept for PNMRX111 without parameter; PNMRX103 rates (and ALL);
//   PNMRX106 datum; PNMRX107 PNMRX300-304 modes (1 now, 2 on change, 3 both; the reports
//   are sent a few a second, interleaved with the NMEA output, as the spec advises);
//   PNMRX108 sequence; PNMRX110 masks (time zone in ZDA, SNR and elevation masks in the fix);
//   PNMRX111 resets (none: per fix procedure; bit field; FACTORY/COLD/WARM/HOT);
//   PNMRX112 power mode; PNMRX113 stops fixes and data extraction until a reset;
//   PNMRX300 almanac upload; PNMRX600 version; PNMRX601 ISP mode (silent until power cycle);
//   PNMRX603 five settings reports (messages 0..4) from the state.
// The VT002 has no "save" command: a power cycle returns to the factory settings.
#include "nemerix/nemerix_actions.h"
#include "sim/receiver.h"
#include "sim/standard_output.h"

#include <array>
#include <deque>
#include <set>
#include <string>

namespace gnss::sim {

class NemerixReceiver : public Receiver {
public:
    explicit NemerixReceiver(const SimOptions &options = {});
    static constexpr int kDefaultBaud = nemerix::kDefaultBaud;
    static constexpr std::array<std::string_view, 7> kMessages = {"GGA", "GLL", "GSA", "GSV",
                                                                  "RMC", "VTG", "ZDA"};
    static constexpr std::array<std::string_view, 5> kReports = {"300", "301", "302", "303", "304"};

    struct Settings {
        std::array<int, 7> rates{};       // seconds, 0 = off (kMessages order)
        std::vector<int> sequence;        // indexes into kMessages
        std::array<int, 5> reportModes{}; // PNMRX107 modes of 300..304
        int protocol = 0, baud = kDefaultBaud, parity = 0;
        int tzMinutes = 0; // PNMRX110 mask 0
        double maxPdop = 10, maxHdop = 10, maxVdop = 10;
        int minSnr = 25, minElevation = 5, noiseFloor = 600, navMode1 = 1, navMode2 = 0;
        int altitude2d = 0, maxAltitude = 18000;
        int datumCorrection = 0, datum = 216, dx = 0, dy = 0, dz = 0;
        std::int64_t iflatRaw = 0, majorARaw = 0;
        int channels = 12, fixProcedure = 0; // 0 hot, 4 cold
        int powerMode = 0, offPeriod = 5;
    };

    const Settings &settings() const { return current_; }
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
    Settings defaults() const;
    std::vector<std::string> sentencesOf(int message, const SkySnapshot &snap) const;
    std::vector<std::string> settingsReports() const;
    // Queues the reports of PNMRX30x (index 0..4) for output.
    void queueReport(int index, const SkySnapshot &snap);
    void applyRate(std::string_view id, int value);
    void softwareReset(std::optional<int> bits, std::string_view named);

    Settings current_;
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
// The record's simulator (Dialect::makeSimulator).
std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options);
} // namespace gnss::nemerix
