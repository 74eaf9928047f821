#pragma once
// NmeaReceiver: a plain NMEA-0183 4.11 receiver (GPS, GLONASS, Galileo, BeiDou, SBAS) with the
// usual default output (GGA, GSA, RMC, VTG, ZDA at 1 Hz and GSV every 2 s, 9600 baud) that answers
// standard queries ($--GPQ,GGA) with the sentence asked for.
#include "sim/receiver.h"
#include "sim/standard_output.h"

namespace gnss::sim {

class NmeaReceiver : public Receiver {
public:
    explicit NmeaReceiver(const SimOptions &options = {});

protected:
    void onCommand(const Sentence &s, const Message *decoded, std::string_view error) override;
    void onEpoch(const SkySnapshot &snap) override;
    void onReset(ResetKind) override {}

private:
    // The sentence(s) of this type for the current epoch; empty when the type is not produced.
    std::vector<std::string> sentencesOf(std::string_view type, const SkySnapshot &snap) const;
    StandardStyle style_;
    unsigned epochs_ = 0;
};

// The plain NMEA receiver (its row in the built-in sim::SimulatorTable).
std::unique_ptr<Receiver> makeNmeaReceiver(const SimOptions &options);

} // namespace gnss::sim
