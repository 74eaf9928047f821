#include "state/signal_history.h"

#include "state/epoch.h"
#include "state/epochs_of_log.h"

#include <algorithm>

namespace gnss {

namespace {
constexpr std::int64_t kDayMs = 86'400'000;
} // namespace

SignalHistory::SignalHistory(std::int64_t spanMs, std::int64_t stepMs)
    : spanMs_(spanMs), stepMs_(std::max<std::int64_t>(1, stepMs)) {}

void SignalHistory::clear() {
    series_.clear();
    pending_.clear();
    cells_ = {};
    epochs_ = 0;
    newestMs_ = lastTimeMs_ = -1;
    dayMs_ = 0;
}

void SignalHistory::setSpan(std::int64_t spanMs) {
    spanMs_ = spanMs;
}

std::int64_t SignalHistory::oldestMs() const {
    std::int64_t oldest = newestMs_;
    for (const auto &[k, samples] : series_)
        if (!samples.empty()) oldest = std::min(oldest, samples.front().timeMs);
    return oldest;
}

void SignalHistory::flush(const Key &k, Pending &p) {
    if (p.count == 0) return;
    series_[k].push_back({p.stepStart, float(p.sum / p.count)});
    p = Pending{};
}

bool SignalHistory::add(const Epoch &e) {
    if (!e.time) return false;
    const std::int64_t tod = e.time->nanos / 1'000'000;
    // Past midnight the time of day starts again: a day is counted.
    if (lastTimeMs_ >= 0 && tod + kDayMs / 2 < lastTimeMs_) dayMs_ += kDayMs;
    lastTimeMs_ = tod;
    const std::int64_t t = tod + dayMs_;
    newestMs_ = std::max(newestMs_, t);
    ++epochs_;
    const std::int64_t step = t - t % stepMs_;
    for (const SatelliteInView &s : e.satellites) {
        if (!s.snr || *s.snr <= 0 || s.sat.system == Constellation::Unknown) continue;
        const Key k{s.sat, s.signalId};
        Pending &p = pending_[k];
        if (p.stepStart != step) {
            flush(k, p);
            p.stepStart = step;
        }
        p.sum += *s.snr;
        ++p.count;
        if (s.elevation && s.azimuth && *s.elevation >= 0 && *s.elevation <= 90) {
            const int az = ((*s.azimuth % 360) + 360) % 360 / (360 / kAzimuthCells);
            const int el = std::min(kElevationCells - 1, *s.elevation / (90 / kElevationCells));
            Cell &c = cells_[std::size_t(el * kAzimuthCells + az)];
            c.sum += *s.snr;
            ++c.count;
        }
    }
    // Signals gone quiet: their last step is kept; what is older than the span goes.
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (it->second.stepStart < step) {
            flush(it->first, it->second);
            it = pending_.erase(it);
        } else {
            ++it;
        }
    }
    if (spanMs_ > 0) {
        for (auto it = series_.begin(); it != series_.end();) {
            auto &samples = it->second;
            while (!samples.empty() && samples.front().timeMs < newestMs_ - spanMs_)
                samples.pop_front();
            it = samples.empty() && !pending_.count(it->first) ? series_.erase(it) : std::next(it);
        }
    }
    return true;
}

SignalHistory historyOfLog(std::string_view log, const DialectRegistry &registry,
                           std::int64_t stepMs, const Dialect *dialect,
                           const std::atomic<bool> *cancel) {
    SignalHistory h(0, stepMs);
    epochsOfLog(
            log, registry, dialect, [&](const Epoch &e) { h.add(e); }, cancel);
    return h;
}

} // namespace gnss
