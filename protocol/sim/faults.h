#pragma once
// Faults the simulator injects on request, for reliability tests of everything that reads a
// receiver (`gnss-sim --faults badcs=0.05,truncate=0.01,binary=0.2,junk=20000,silence=3@10,
// noreply=PNVGRTK,slowreply=800,hangup=30,powercut=PNVGCFG,hangupon=PNVGPPS/1`).
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::sim {

struct FaultSpec {
    double badChecksum = 0; // probability that a sentence's checksum is wrong
    double truncate = 0;    // probability that a sentence is cut short (no terminator)
    double binary = 0;      // probability per epoch of an RTCM3-like frame between sentences
    // junk=BYTES: a flood of random bytes (never '$' or '!') between sentences, this many a second,
    // as from a receiver gone mad or a line at the wrong settings; past what the line carries too.
    double junkPerSecond = 0;
    double silenceFor = 0;   // seconds of silence (no output, no replies: hung) ...
    double silenceAt = -1;   // ... starting at this simulated time (-1: none)
    double silenceEvery = 0; // and again every this many seconds (0: once)
    // Commands whose replies never come: a command's address ("PNVGRTK") or its first field
    // ("RQUERY" for $GPSGG,RQUERY). Several are joined with '+': noreply=PNVGRTK+PNVGCFG.
    std::vector<std::string> noReply;
    double slowReplyMs = 0;  // replies come this late (simulated milliseconds)
    double hangupAfter = -1; // the line drops after this many simulated seconds (-1: never)
    // hangup=T/DOWN[xCOUNT]: the line drops once a program has had it for T seconds and is back
    // DOWN seconds later (gnss-sim: a new pseudo-terminal), COUNT times (0: without end); the
    // receiver runs on meanwhile. Without /DOWN the line drops T seconds after the start, for
    // good (Receiver::hungUp()). The coming-back kind is gnss-sim's, which owns the line.
    double hangupDown = 0;
    int hangupTimes = 0;
    // powercut=CMD[+CMD]: the power fails when the first of these commands arrives, before it is
    // carried out or answered: the receiver is off (deaf and silent) for kPowerCutSeconds, then
    // boots from its flash. A save to flash it interrupts is not made (a flash write either
    // completes or not; here: not), so the receiver comes back with what its flash held before.
    // Names as noreply takes them; once per run.
    std::vector<std::string> powerCut;
    static constexpr double kPowerCutSeconds = 2.0;
    // hangupon=CMD[+CMD][/DOWN]: the line drops the moment the first of these commands arrives
    // (a cable pulled in the middle of a settings apply): the receiver carries the command out,
    // its answer is lost with the line, and what the host sent after it is not heard. DOWN
    // seconds later (default 1) the line is back (gnss-sim: a new pseudo-terminal); the receiver
    // runs on meanwhile. Names as noreply takes them; once per run; gnss-sim's, which owns the
    // line (Receiver::takeLineDrop()).
    std::vector<std::string> hangupOn;
    double hangupOnDown = 1.0;

    bool any() const;
    bool silentAt(double time) const;
    bool replySuppressed(std::string_view address, std::string_view firstField) const;
    bool cutsPower(std::string_view address, std::string_view firstField) const;
    bool hangsUpOn(std::string_view address, std::string_view firstField) const;
    // The hang-up comes back (hangup=T/DOWN), rather than ending the line.
    bool hangupRepeats() const { return hangupAfter >= 0 && hangupDown > 0; }
};

// Parses "key=value,key=value". Empty text → no faults. On error returns nullopt and sets
// `error` naming the option and what it accepts.
std::optional<FaultSpec> parseFaults(std::string_view spec, std::string &error);

// An RTCM3 frame (0xD3, 10-bit length, payload starting with a 12-bit message number, CRC-24Q)
// with random payload: what a receiver's port carries when RTCM output shares it.
std::string rtcm3Frame(std::mt19937 &rng, int messageNumber, int payloadLength);
std::uint32_t crc24q(std::string_view bytes);

} // namespace gnss::sim
