#pragma once
// Comparison: several receivers on the same sky, matched epoch by epoch on UTC time. The first
// receiver is the reference: every difference is another receiver minus it. Each epoch that
// every receiver reported gives a Match (position difference east/north/up, C/N0 of the
// satellites and signals both track side by side, satellites only one of them has); the
// differences accumulate into a Report (mean, median, p95; CEP50/CEP95 of the horizontal
// difference; C/N0 per constellation; fix availability per receiver).
//
//     Comparison c({"NV08C-RTK /dev/ttyUSB0", "GeoS-5 /dev/ttyUSB1"});
//     c.add(0, *Observation::of(epoch), onMatch); // in each receiver's own time order
//     Report r = c.report();
//
// Epochs are held until every receiver has reported their time, at most kHoldMs behind the
// newest: a receiver that skips a time, or stops, costs that time and no memory.
#include "compare/observation.h"
#include "compare/spread.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gnss::compare {

// The C/N0 of one satellite's signal on the reference and on another receiver (dB-Hz).
struct SignalPair {
    SatelliteRef sat;
    int signalId = 0; // the reference's
    int reference = 0, other = 0;
};

// One receiver against the reference at one matched time.
struct Difference {
    std::optional<double> east, north, up, horizontal; // metres, other minus reference
    std::vector<SignalPair> cn0;
    std::vector<SatelliteRef> onlyInReference, onlyInOther;
};

struct Match {
    std::int64_t timeMs = 0;                       // UTC time of day
    std::vector<const Observation *> observations; // one per receiver
    std::vector<Difference> differences;           // one per receiver after the first
};

// A match kept by value: what a window of the last minutes holds (the Compare dock's).
struct MatchRecord {
    std::int64_t timeMs = 0;             // UTC time of day
    std::vector<FixType> fixes;          // one per receiver
    std::vector<Difference> differences; // one per receiver after the first
    static MatchRecord of(const Match &m);
};

struct ConstellationCn0 {
    Constellation system = Constellation::Unknown;
    Spread difference;  // other minus reference, dB
    int satellites = 0; // compared at least once
};

struct SatelliteCount {
    SatelliteRef sat;
    std::size_t epochs = 0;
};

// A receiver after the first, against the reference, over the matched epochs.
struct PairReport {
    Spread east, north, up, horizontal;
    double cep50 = 0, cep95 = 0; // of the horizontal difference
    Spread cn0;                  // over every satellite and signal both track
    std::vector<ConstellationCn0> perConstellation;
    std::vector<SatelliteCount> onlyInReference, onlyInThis;
};

struct FixCount {
    FixType fix = FixType::None;
    std::size_t epochs = 0;
};

struct ReceiverReport {
    std::string name, dialect;
    std::size_t epochs = 0;      // with a UTC time
    std::vector<FixCount> fixes; // in FixType order, those seen
};

struct Report {
    std::vector<ReceiverReport> receivers;
    std::size_t matchedEpochs = 0;
    std::vector<PairReport> pairs; // receivers[1..]
};

class Comparison {
public:
    static constexpr std::int64_t kHoldMs = 10'000;
    using MatchFn = std::function<void(const Match &)>;

    explicit Comparison(std::vector<std::string> names);

    std::size_t receivers() const { return receivers_.size(); }
    void setDialect(std::size_t receiver, std::string dialect);
    // A receiver's name once it is known better (its model found after the start).
    void setName(std::size_t receiver, std::string name);
    // One epoch of `receiver`, in its time order (a time of day far before its last is the next
    // day). `onMatch` is called when it completes a time every receiver reported.
    void add(std::size_t receiver, Observation o, const MatchFn &onMatch = {});
    // Whole recordings, one per receiver (each in its own time order), added in UTC order across
    // them as live receivers would have sent them: what comparing logs needs.
    void addInTimeOrder(const std::vector<std::vector<Observation>> &recordings,
                        const MatchFn &onMatch = {});
    std::size_t matchedEpochs() const { return matched_; }
    Report report() const;

    // One receiver against the reference at one time (no state): what a Match holds.
    static Difference differenceOf(const Observation &reference, const Observation &other);
    // The report of these matches alone (a window of the last minutes): each receiver's epochs
    // and fixes are those of the matches.
    static Report reportOf(const std::vector<std::string> &names,
                           const std::deque<MatchRecord> &matches);

private:
    struct Receiver {
        std::string name, dialect;
        std::map<std::int64_t, Observation> held; // by UTC time (ms, days counted)
        std::int64_t lastTimeMs = -1, dayMs = 0;
        std::size_t epochs = 0;
        std::map<FixType, std::size_t> fixes;
    };
    struct Accumulator {
        std::vector<double> east, north, up, horizontal, cn0;
        std::map<Constellation, std::vector<double>> cn0ByConstellation;
        std::map<Constellation, std::set<int>> compared; // PRNs whose C/N0 was compared
        std::map<std::pair<Constellation, int>, std::size_t> onlyInReference, onlyInThis;
    };
    void match(std::int64_t key, const MatchFn &onMatch);
    static void accumulate(Accumulator &a, const Difference &d);
    static PairReport pairReport(const Accumulator &a);

    std::vector<Receiver> receivers_;
    std::vector<Accumulator> pairs_; // receivers_[1..]
    std::size_t matched_ = 0;
    std::int64_t lastMatched_ = -1;
};

} // namespace gnss::compare
