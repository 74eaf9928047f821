#pragma once
// Ephemeris assembly: PNMRX301 arrives as three messages per satellite (subframes 1, 2, 3);
// EphemerisAssembler joins them and hands out one Ephemeris per satellite once all three have
// arrived with a matching issue of data. Plain C++, usable by the GUI and the simulator.
#include "nemerix/nemerix_messages.h"

#include <array>
#include <optional>

namespace gnss::nemerix {

// One satellite's complete ephemeris (raw values; engineering units via value()).
struct Ephemeris : Message {
    static const MessageType kType;
    Ephemeris() : Message(kType) {}
    int sv = 0;
    std::array<std::optional<std::int64_t>, EphemerisSubframe::kMaxFields> sf1{}, sf2{}, sf3{};
    // IODE of subframes 2 and 3 equal the low 8 bits of IODC.
    bool consistent() const;
    // Engineering value of a field (EphemerisSubframe::Sf1/Sf2/Sf3 index); 0 when absent.
    double value(int subframe, int field) const;
    void writeJson(JsonWriter &w) const override;
};

class EphemerisAssembler {
public:
    // Adds one subframe message; returns the satellite's ephemeris when it is complete.
    std::optional<Ephemeris> add(const EphemerisSubframe &part);
    // Subframes held for `sv` (bit 0 = subframe 1, ...).
    int pendingMask(int sv) const;
    void reset();

private:
    struct Pending {
        Ephemeris eph;
        unsigned have = 0;
    };
    std::array<Pending, 32> pending_{};
};

} // namespace gnss::nemerix
