#pragma once
// Receiver: one simulated GNSS receiver, driven from outside. Plain C++, no threads, no clock:
// whoever runs it (gnss-sim over a pseudo-terminal/TCP/stdout, a QIODevice in the link layer, a
// test) feeds the host's bytes in, advances simulated time and takes the receiver's bytes out:
//
//     auto rx = simulators.make("nvs", options); // a SimulatorTable (simulator_table.h)
//     rx->receive("$PNVGRTK,PVTRATE,10*..\r\n");
//     rx->advance(0.25);
//     std::string bytes = rx->takeOutput();
//
// Each family's subclass, in its own folder (nvs/sim/nvs_sim_receiver.cpp, ...) and made by its
// row in a SimulatorTable (protocol/builtin/simulators.cpp), holds the spec's behaviour:
// default output list, rates and baud; how each command is answered; what is saved to flash.
// Commands are read with the dialect's own decoders (gnss::StreamDecoder) and replies built with
// its encoders, so the simulator and the rest of the program cannot disagree on syntax.
#include "core/dialect.h"
#include "core/dialect_registry.h"
#include "core/field_types.h"
#include "core/stream_decoder.h"
#include "sim/differences.h"
#include "sim/faults.h"
#include "sim/sky_model.h"
#include "sim/ttff_model.h"

#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::sim {

struct SimOptions {
    std::uint32_t seed = 1;
    int baud = 0; // starting baud; 0 = the receiver's default
    FaultSpec faults;
    Observer observer;
    // An RTK rover corrects itself from a base inside the simulator (a demonstration without a
    // caster). Otherwise, as a real rover, it waits for RTCM 3 from the host on its port.
    bool internalBase = false;
    // What it reports otherwise than the truth, on purpose (differences.h).
    Differences differences;
    // Seconds after 10:00:00 UTC (kStartSecondOfDay) at which it starts: simulators started at
    // different moments with the same seed and their start set from one clock (gnss-sim
    // --start now) see the same sky at the same UTC.
    double startAfter = 0;
    // The share of the modelled noise reported (SkyModel::setNoise): 0 reports the truth, so
    // receivers of different families on one sky differ by their Differences alone.
    double noise = 1;
    // Times to first fix per kind of start set on purpose (gnss-sim --ttff), over the family's.
    TtffModel ttff;
};

class Receiver {
public:
    virtual ~Receiver();
    Receiver(const Receiver &) = delete;
    Receiver &operator=(const Receiver &) = delete;

    // Bytes from the host. Ignored while the line speed differs from the receiver's (a UART at
    // the wrong speed reads garbage), after a hang-up and while the power is off (powercut).
    void receive(std::string_view bytes);
    // Runs the receiver for `seconds` of simulated time (epochs, delayed replies, baud switches).
    void advance(double seconds);
    // Everything the receiver sent since the last call.
    std::string takeOutput();
    // What it sent on another of its ports (`port` as its dialect numbers them, not the host's)
    // since the last call: an NV08C-RTK base's RTCM on COM2. Not paced, no faults.
    std::string takeOutput(int port);

    // The receiver's current baud, and the speed the host set on its side of the line
    // (0 = unknown/not a serial line: never garbled). While they differ, output is garbled
    // and input ignored.
    int baud() const { return baud_; }
    void setLineBaud(int baud) { lineBaud_ = baud; }
    int lineBaud() const { return lineBaud_; }
    bool baudMismatch() const { return lineBaud_ > 0 && lineBaud_ != baud_; }

    // Output sentences dropped because the line speed could not carry them (bytes per second =
    // baud / 10): the receiver's UART transmit buffer holds kTxBuffer bytes not yet on the
    // line; a sentence that does not fit is dropped (replies are never dropped). A list that
    // needs more than the line speed first fills the buffer, then loses sentences every epoch.
    std::int64_t droppedSentences() const { return dropped_; }
    static constexpr double kTxBuffer = 4096;

    // The hang-up fault fired: the transport should close the line.
    bool hungUp() const { return hungUp_; }
    // The hangupon fault fired since the last call: the transport drops the line now (before
    // anything more is written to it) and brings it back faults.hangupOnDown seconds later; the
    // receiver runs on. Until then what the host sends is not heard.
    bool takeLineDrop() {
        const bool due = lineDropDue_;
        lineDropDue_ = false;
        return due;
    }
    // Simulated seconds since start.
    double time() const { return now_; }
    // Simulated power cycle: settings come back from flash, the fix sequence restarts.
    void powerCycle() { reset(ResetKind::PowerCycle); }
    // The powercut fault fired and the receiver has not booted again yet: deaf and silent.
    bool poweredOff() const { return now_ < offUntil_; }

    const Dialect &dialect() const { return dialect_; }
    // Seconds between navigation epochs (PVT rate).
    virtual double epochInterval() const { return 1.0; }
    // The current fix (for tests and status displays).
    FixKind currentFix() const { return lastFix_; }
    const SkySnapshot &lastSnapshot() const { return last_; }

    // UTC of the simulated start: 2024-03-15 10:00:00 (a Friday; GPS-UTC = 18 s), plus
    // SimOptions::startAfter.
    static constexpr double kStartSecondOfDay = 10 * 3600.0;
    static constexpr int kLeapSeconds = 18;

protected:
    // A receiver of `dialect` (commands are read with its decoders and the standard ones only),
    // starting at the record's default speed.
    Receiver(const Dialect &dialect, const SimOptions &options);
    Receiver(const Dialect &dialect, int defaultBaud, const SimOptions &options);

    // One sentence received from the host (checksum accepted by the dialect's policy).
    // `decoded` is the dialect's decoding, nullptr when it did not decode (`error` says why).
    virtual void onCommand(const Sentence &s, const Message *decoded, std::string_view error) = 0;
    // One navigation epoch: write the epoch's output with send().
    virtual void onEpoch(const SkySnapshot &snap) = 0;
    // Settings back to the saved copy (PowerCycle) and engine state cleared (all kinds).
    virtual void onReset(ResetKind kind) = 0;
    // Every byte from the host, before the commands in it are decoded (RTCM corrections).
    virtual void onHostBytes(std::string_view bytes) { (void)bytes; }
    // Which satellites the receiver uses (from its settings).
    virtual UseMask useMask() const { return {}; }
    // The fix the engine has reached `seconds` after it started tracking (RTK receivers refine).
    virtual FixKind fixAfter(double seconds) const;

    // Restarts the engine (fix sequence): used by reset commands.
    void reset(ResetKind kind);
    // Sends an output sentence (CR LF added; faults applied).
    void send(const std::string &sentence);
    // Sends bytes as they are (an RTCM 3 frame), on the host's port when `port` is 0, else on
    // that other port (takeOutput(port)).
    void sendBytes(std::string_view bytes, int port = 0);
    // Sends a reply to `command` (noreply/slowreply faults apply). `thenBaud` > 0 switches the
    // receiver's baud once this reply is out (PNVGRZA, BDR...). Replies to one command keep
    // their order.
    void reply(const Sentence &command, const std::string &sentence, int thenBaud = 0);
    // Changes the PVT rate: the next epoch is on the new grid.
    void rescheduleEpochs();
    // The time to first fix of the last start, seconds (drawn from the TTFF model).
    double ttff() const { return ttff_; }
    // A family's own times to first fix (its datasheet's), under what the options set: the
    // power-on start is drawn again from them. Called from the family's constructor.
    void setFamilyTtff(const TtffModel &family);
    double sinceTracking() const { return now_ - trackingSince_; }

    // Seconds since 10:00:00 UTC of the first day: time() plus the start (whole seconds of it
    // are whole seconds of UTC, for once-a-second and every-N-seconds outputs).
    double utcSeconds() const { return now_ + options_.startAfter; }
    // Time helpers for output: UTC of the simulated time.
    double utcSecondOfDay() const;
    Date utcDate() const;
    double gpsTimeOfWeek() const;
    int gpsWeek() const;

    std::mt19937 &random() { return sky_.random(); }
    SkyModel &sky() { return sky_; }
    const SimOptions &options() const { return options_; }
    int defaultBaud() const { return defaultBaud_; }
    void setBaudNow(int b) { baud_ = b; }

private:
    struct Pending {
        double at;
        std::string text;
        int thenBaud;
    };
    void runEpoch();
    double nextOnGrid() const;
    void flushDue();
    // The powercut fault, when `command` is one it names: true when the power went.
    bool cutPowerAt(const Sentence &command);
    // The hangupon fault, when `command` is one it names (the command is still carried out).
    void dropLineAt(const Sentence &command);
    // The hang-up fault for good (hangup=T) is due.
    bool hangsUp() const;
    void write(std::string bytes);
    // Takes the line time of `bytes`; false (nothing taken) when `mayDrop` and it does not fit.
    bool takeLineTime(std::size_t bytes, bool mayDrop);
    std::string garble(std::size_t n);

    const Dialect &dialect_;
    SimOptions options_;
    DialectRegistry registry_;
    StreamDecoder decoder_;
    SkyModel sky_;
    std::mt19937 faultRng_;
    int defaultBaud_;
    int baud_;
    int lineBaud_ = 0;
    double now_ = 0;
    double lineFreeAt_ = 0; // when the UART has sent everything queued so far
    std::int64_t dropped_ = 0;
    double nextEpoch_ = 0;
    double trackingSince_ = 0;
    double ttff_ = 0;
    TtffModel ttffModel_;
    std::mt19937 ttffRng_;
    bool hungUp_ = false;
    double offUntil_ = -1;      // the powercut fault: off until then, then a power cycle
    bool powerCutDone_ = false; // (once per run)
    bool lineDropDue_ = false;  // the hangupon fault fired, the transport has not taken it yet
    bool lineDropDone_ = false; // (once per run)
    FixKind lastFix_ = FixKind::None;
    SkySnapshot last_;
    std::vector<Pending> pending_;
    std::string out_;
    std::map<int, std::string> otherPorts_; // output of ports other than the host's
    // Output held back by the latency difference: when it may leave, and the bytes.
    std::vector<std::pair<double, std::string>> delayed_;
};

} // namespace gnss::sim
