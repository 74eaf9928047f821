#pragma once
// EpochAssembler: decoded messages in, one Epoch per navigation epoch out.
//
// An epoch ends when a sentence carrying a different fix time arrives (or at flush()). Sentences
// without a time (GSA, GSV) belong to the epoch in progress. The sky carries over between epochs:
// each GSV group (talker + signal id) replaces its own satellites only when it arrives whole, so a
// multi-part group is applied whole or not at all; groups not refreshed for a while expire.
#include "core/dialect.h"
#include "core/function_ref.h"
#include "state/epoch.h"

#include <array>
#include <bitset>
#include <string>
#include <vector>

namespace gnss {

namespace nmea {
struct Gsa;
struct Gsv;
} // namespace nmea

class EpochAssembler {
public:
    using Callback = FunctionRef<void(const Epoch &)>;

    explicit EpochAssembler(const Dialect *dialect = nullptr) : dialect_(dialect) {}
    void setDialect(const Dialect *d) { dialect_ = d; }
    // Drops the satellites in view gathered so far, in the epoch in progress and in every GSV
    // group: what a live view does when the receiver's dialect becomes known, since they were
    // numbered without it.
    void forgetSatellites() {
        groups_.clear();
        current_.satellites.clear();
    }

    // Adds one decoded message; calls onEpoch when it closes the epoch in progress.
    void add(const Sentence &s, const Message &m, const Callback &onEpoch);
    // Emits the epoch in progress, if it holds anything.
    void flush(const Callback &onEpoch);

    std::uint64_t epochs() const { return epochs_; }
    // Whether both would turn the same messages into the same epochs from here on (what they
    // hold, not how many epochs they have counted): how a log decoded in pieces finds the point
    // where a piece started afresh agrees with the log read from its start.
    bool sameFuture(const EpochAssembler &other) const;
    std::uint64_t incompleteGsvGroups() const { return incompleteGroups_; }

private:
    struct GsvGroup {
        std::uint32_t key = 0;                   // talker (2 chars) and signal id
        std::vector<SatelliteInView> satellites; // committed
        std::vector<SatelliteInView> pending;    // being assembled
        int expectedTotal = 0;
        int nextIndex = 0;
        std::uint64_t refreshedEpoch = 0;
    };
    void addGsv(const Sentence &s, const nmea::Gsv &gsv);
    void addGsa(const nmea::Gsa &a);
    void startEpochIfTimeChanged(const std::optional<TimeOfDay> &t, const Callback &onEpoch);
    void closeEpoch(const Callback &onEpoch);
    FixType fixFromQuality(int q) const;
    FixType fixFromMode(char mode) const;
    int modeRank(char mode) const;
    char bestMode(std::string_view modes) const;

    const Dialect *dialect_;
    Epoch current_;
    bool hasContent_ = false;
    GsvGroup &group(std::uint32_t key);
    void markUsed(SatelliteRef s) {
        if (s.prn >= 0 && s.prn < 256) used_.set(static_cast<std::size_t>(s.system) * 256 + s.prn);
    }
    bool isUsed(SatelliteRef s) const {
        return s.prn >= 0 && s.prn < 256 &&
               used_.test(static_cast<std::size_t>(s.system) * 256 + s.prn);
    }

    std::vector<GsvGroup> groups_; // a handful (one per talker and signal): linear search wins
    std::bitset<8 * 256> used_; // used in fix, from this epoch's GSA (or the last), by system/PRN
    int usedCount_ = 0;
    bool usedThisEpoch_ = false;
    std::optional<double> lastPdop_, lastHdop_,
            lastVdop_; // from the latest GSA (kept when GSA is slower)
    std::optional<Date> lastDate_;
    std::optional<int> ggaQuality_, gsaFix_;
    std::optional<char> rmcMode_, rmcStatus_;
    std::string gnsMode_;
    std::uint64_t epochs_ = 0;
    std::uint64_t incompleteGroups_ = 0;
};

} // namespace gnss
