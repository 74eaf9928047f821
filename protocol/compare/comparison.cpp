#include "compare/comparison.h"

#include "core/wgs84.h"

#include <algorithm>
#include <cmath>

namespace gnss::compare {

namespace {

constexpr std::int64_t kDayMs = 86'400'000;

// A receiver's levels of one satellite.
std::vector<const SignalLevel *> signalsOf(const Observation &o, SatelliteRef sat) {
    std::vector<const SignalLevel *> out;
    for (const SignalLevel &s : o.levels)
        if (s.sat == sat) out.push_back(&s);
    return out;
}

bool before(SatelliteRef a, SatelliteRef b) {
    return std::pair(a.system, a.prn) < std::pair(b.system, b.prn);
}

std::vector<SatelliteRef> satellitesOf(const Observation &o) {
    std::vector<SatelliteRef> out;
    // A satellite of no known system (numbered before the receiver's dialect was known) cannot
    // be matched with another receiver's: left out.
    for (const SignalLevel &s : o.levels)
        if (s.sat.system != Constellation::Unknown &&
            std::find(out.begin(), out.end(), s.sat) == out.end())
            out.push_back(s.sat);
    std::sort(out.begin(), out.end(), before);
    return out;
}

std::vector<SatelliteCount> counted(const std::map<std::pair<Constellation, int>, std::size_t> &m) {
    std::vector<SatelliteCount> out;
    for (const auto &[sat, n] : m) out.push_back({{sat.first, sat.second}, n});
    return out;
}

} // namespace

Comparison::Comparison(std::vector<std::string> names) {
    for (auto &n : names) receivers_.push_back(Receiver{std::move(n), {}, {}, -1, 0, 0, {}});
    pairs_.resize(receivers_.empty() ? 0 : receivers_.size() - 1);
}

void Comparison::setDialect(std::size_t receiver, std::string dialect) {
    if (receiver < receivers_.size()) receivers_[receiver].dialect = std::move(dialect);
}

void Comparison::setName(std::size_t receiver, std::string name) {
    if (receiver < receivers_.size()) receivers_[receiver].name = std::move(name);
}

Difference Comparison::differenceOf(const Observation &ref, const Observation &other) {
    Difference d;
    if (ref.hasPosition() && other.hasPosition()) {
        const wgs84::MetresPerDegree m = wgs84::metresPerDegree(*ref.lat);
        double dLon = *other.lon - *ref.lon;
        if (dLon > 180) dLon -= 360;
        if (dLon < -180) dLon += 360;
        d.east = dLon * m.east;
        d.north = (*other.lat - *ref.lat) * m.north;
        d.horizontal = std::hypot(*d.east, *d.north);
        if (ref.height && other.height) d.up = *other.height - *ref.height;
    }
    const std::vector<SatelliteRef> a = satellitesOf(ref), b = satellitesOf(other);
    for (SatelliteRef sat : a) {
        if (!std::binary_search(b.begin(), b.end(), sat, before)) {
            d.onlyInReference.push_back(sat);
            continue;
        }
        const auto mine = signalsOf(ref, sat), theirs = signalsOf(other, sat);
        bool any = false;
        for (const SignalLevel *r : mine)
            for (const SignalLevel *o : theirs)
                if (r->signalId == o->signalId) {
                    d.cn0.push_back({sat, r->signalId, r->cn0, o->cn0});
                    any = true;
                }
        if (!any) {
            // Signals numbered differently (one receiver says none): each one's first signal,
            // its primary (L1, G1, E1, B1) in every receiver here.
            auto first = [](const std::vector<const SignalLevel *> &v) {
                return *std::min_element(v.begin(), v.end(), [](auto *x, auto *y) {
                    return x->signalId < y->signalId;
                });
            };
            d.cn0.push_back({sat, first(mine)->signalId, first(mine)->cn0, first(theirs)->cn0});
        }
    }
    for (SatelliteRef sat : b)
        if (!std::binary_search(a.begin(), a.end(), sat, before)) d.onlyInOther.push_back(sat);
    return d;
}

void Comparison::add(std::size_t receiver, Observation o, const MatchFn &onMatch) {
    if (receiver >= receivers_.size()) return;
    Receiver &r = receivers_[receiver];
    // Past midnight the time of day starts again: a day is counted.
    if (r.lastTimeMs >= 0 && o.timeMs + kDayMs / 2 < r.lastTimeMs) r.dayMs += kDayMs;
    r.lastTimeMs = o.timeMs;
    const std::int64_t key = o.timeMs + r.dayMs;
    ++r.epochs;
    ++r.fixes[o.fix];
    if (key <= lastMatched_) return; // the others have moved on
    r.held[key] = std::move(o);
    // What no other receiver can still complete goes.
    while (!r.held.empty() && r.held.begin()->first < key - kHoldMs) r.held.erase(r.held.begin());
    for (const Receiver &x : receivers_)
        if (!x.held.count(key)) return;
    match(key, onMatch);
}

void Comparison::addInTimeOrder(const std::vector<std::vector<Observation>> &recordings,
                                const MatchFn &onMatch) {
    // Each recording's times with its days counted, then a merge on them.
    std::vector<std::vector<std::int64_t>> keys(recordings.size());
    for (std::size_t r = 0; r < recordings.size(); ++r) {
        std::int64_t day = 0, last = -1;
        for (const Observation &o : recordings[r]) {
            if (last >= 0 && o.timeMs + kDayMs / 2 < last) day += kDayMs;
            last = o.timeMs;
            keys[r].push_back(o.timeMs + day);
        }
    }
    std::vector<std::size_t> next(recordings.size(), 0);
    for (;;) {
        std::size_t pick = recordings.size();
        for (std::size_t r = 0; r < recordings.size(); ++r)
            if (next[r] < keys[r].size() &&
                (pick == recordings.size() || keys[r][next[r]] < keys[pick][next[pick]]))
                pick = r;
        if (pick == recordings.size()) return;
        add(pick, recordings[pick][next[pick]++], onMatch);
    }
}

void Comparison::match(std::int64_t key, const MatchFn &onMatch) {
    Match m;
    m.timeMs = key % kDayMs;
    for (const Receiver &x : receivers_) m.observations.push_back(&x.held.at(key));
    const Observation &ref = *m.observations.front();
    for (std::size_t i = 1; i < receivers_.size(); ++i) {
        Difference d = differenceOf(ref, *m.observations[i]);
        accumulate(pairs_[i - 1], d);
        m.differences.push_back(std::move(d));
    }
    ++matched_;
    if (onMatch) onMatch(m);
    lastMatched_ = key;
    for (Receiver &x : receivers_) x.held.erase(x.held.begin(), x.held.upper_bound(key));
}

void Comparison::accumulate(Accumulator &a, const Difference &d) {
    if (d.horizontal) {
        a.east.push_back(*d.east);
        a.north.push_back(*d.north);
        a.horizontal.push_back(*d.horizontal);
    }
    if (d.up) a.up.push_back(*d.up);
    for (const SignalPair &p : d.cn0) {
        const double diff = p.other - p.reference;
        a.cn0.push_back(diff);
        a.cn0ByConstellation[p.sat.system].push_back(diff);
        a.compared[p.sat.system].insert(p.sat.prn);
    }
    for (SatelliteRef s : d.onlyInReference) ++a.onlyInReference[{s.system, s.prn}];
    for (SatelliteRef s : d.onlyInOther) ++a.onlyInThis[{s.system, s.prn}];
}

PairReport Comparison::pairReport(const Accumulator &a) {
    PairReport p;
    auto spread = [](std::vector<double> v) { return spreadOf(v); };
    p.east = spread(a.east);
    p.north = spread(a.north);
    p.up = spread(a.up);
    std::vector<double> h = a.horizontal;
    p.horizontal = spreadOf(h); // sorts h
    p.cep50 = quantile(h, 0.50);
    p.cep95 = quantile(h, 0.95);
    p.cn0 = spread(a.cn0);
    for (const auto &[system, values] : a.cn0ByConstellation) {
        const auto sats = a.compared.find(system);
        p.perConstellation.push_back(
                {system, spread(values),
                 sats == a.compared.end() ? 0 : static_cast<int>(sats->second.size())});
    }
    p.onlyInReference = counted(a.onlyInReference);
    p.onlyInThis = counted(a.onlyInThis);
    return p;
}

MatchRecord MatchRecord::of(const Match &m) {
    MatchRecord r;
    r.timeMs = m.timeMs;
    for (const Observation *o : m.observations) r.fixes.push_back(o->fix);
    r.differences = m.differences;
    return r;
}

Report Comparison::reportOf(const std::vector<std::string> &names,
                            const std::deque<MatchRecord> &matches) {
    Report r;
    r.matchedEpochs = matches.size();
    std::vector<std::map<FixType, std::size_t>> fixes(names.size());
    std::vector<Accumulator> pairs(names.empty() ? 0 : names.size() - 1);
    for (const MatchRecord &m : matches) {
        for (std::size_t i = 0; i < fixes.size() && i < m.fixes.size(); ++i) ++fixes[i][m.fixes[i]];
        for (std::size_t i = 0; i < pairs.size() && i < m.differences.size(); ++i)
            accumulate(pairs[i], m.differences[i]);
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        ReceiverReport rr{names[i], {}, matches.size(), {}};
        for (const auto &[fix, n] : fixes[i]) rr.fixes.push_back({fix, n});
        r.receivers.push_back(std::move(rr));
    }
    for (const Accumulator &a : pairs) r.pairs.push_back(pairReport(a));
    return r;
}

Report Comparison::report() const {
    Report r;
    r.matchedEpochs = matched_;
    for (const Receiver &x : receivers_) {
        ReceiverReport rr{x.name, x.dialect, x.epochs, {}};
        for (const auto &[fix, n] : x.fixes) rr.fixes.push_back({fix, n});
        r.receivers.push_back(std::move(rr));
    }
    for (const Accumulator &a : pairs_) r.pairs.push_back(pairReport(a));
    return r;
}

} // namespace gnss::compare
