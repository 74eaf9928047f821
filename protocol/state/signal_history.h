#pragma once
// SignalHistory: the C/N0 of each satellite and signal over time, and a polar map of C/N0 over the
// sky (azimuth × elevation cells: mean C/N0 and count), from epochs. What a receiver's Signal
// history dock draws live (the last minutes) and the log viewer over a whole log or a range.
//
// Samples are kept at most one per `stepMs` per signal (the mean of the epochs in that step), so
// an hour at 10 Hz costs what an hour at 1 Hz does; those older than `spanMs` before the newest
// go (0: keep all, for a log). The polar map counts every epoch since the last clear().
#include "core/satellite.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <string_view>
#include <tuple>

namespace gnss {

struct Dialect;
struct Epoch;
class DialectRegistry;

class SignalHistory {
public:
    struct Key {
        SatelliteRef sat;
        int signalId = 0;
        bool operator<(const Key &o) const {
            return std::tuple(int(sat.system), sat.prn, signalId) <
                   std::tuple(int(o.sat.system), o.sat.prn, o.signalId);
        }
        bool operator==(const Key &o) const = default;
    };
    struct Sample {
        std::int64_t timeMs = 0; // UTC time, days counted from the first epoch's
        float cn0 = 0;           // dB-Hz
    };
    struct Cell {
        double sum = 0;
        std::uint32_t count = 0;
        double mean() const { return count ? sum / count : 0; }
    };
    static constexpr int kAzimuthCells = 36;  // 10° each
    static constexpr int kElevationCells = 9; // 10° each, 0 at the horizon

    explicit SignalHistory(std::int64_t spanMs = 600'000, std::int64_t stepMs = 1000);

    // An epoch with a time; one without is skipped (false).
    bool add(const Epoch &e);
    void clear();
    void setSpan(std::int64_t spanMs);
    std::int64_t span() const { return spanMs_; }

    const std::map<Key, std::deque<Sample>> &series() const { return series_; }
    const Cell &cell(int azimuthCell, int elevationCell) const {
        return cells_[std::size_t(elevationCell * kAzimuthCells + azimuthCell)];
    }
    std::uint64_t epochs() const { return epochs_; }
    std::int64_t newestMs() const { return newestMs_; }
    std::int64_t oldestMs() const;

private:
    struct Pending {
        std::int64_t stepStart = -1;
        double sum = 0;
        int count = 0;
    };
    void flush(const Key &k, Pending &p);

    std::int64_t spanMs_, stepMs_;
    std::map<Key, std::deque<Sample>> series_;
    std::map<Key, Pending> pending_;
    std::array<Cell, kAzimuthCells * kElevationCells> cells_{};
    std::uint64_t epochs_ = 0;
    std::int64_t newestMs_ = -1, lastTimeMs_ = -1, dayMs_ = 0;
};

// A log, or a range of one (LogView::slice), decoded front to back: its signals' history (span 0,
// one sample per `stepMs`). `dialect`: the one in force where the bytes begin (nullptr: recognised
// as it goes). Stops early, with what it has, when `cancel` turns true.
SignalHistory historyOfLog(std::string_view log, const DialectRegistry &registry,
                           std::int64_t stepMs, const Dialect *dialect = nullptr,
                           const std::atomic<bool> *cancel = nullptr);

} // namespace gnss
