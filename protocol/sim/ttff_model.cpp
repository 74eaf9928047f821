#include "sim/ttff_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace gnss::sim {

namespace {

bool number(std::string_view s, double &out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

} // namespace

TtffModel TtffModel::builtin() {
    TtffModel m;
    m.power = {3.0, 0};
    m.hot = {2.0, 0};
    m.warm = {6.0, 0};
    m.cold = {15.0, 0};
    return m;
}

TtffModel::Dist &TtffModel::of(ResetKind k) {
    switch (k) {
    case ResetKind::Cold: return cold;
    case ResetKind::Warm: return warm;
    case ResetKind::Hot: return hot;
    case ResetKind::PowerCycle: break;
    }
    return power;
}

const TtffModel::Dist &TtffModel::of(ResetKind k) const {
    return const_cast<TtffModel *>(this)->of(k);
}

TtffModel TtffModel::over(const TtffModel &base) const {
    TtffModel m = base;
    for (ResetKind k : {ResetKind::PowerCycle, ResetKind::Cold, ResetKind::Warm, ResetKind::Hot})
        if (of(k).set()) m.of(k) = of(k);
    return m;
}

double TtffModel::draw(ResetKind k, std::mt19937 &rng) const {
    const Dist &d = of(k);
    const double mean = std::max(0.0, d.mean);
    if (d.spread <= 0 || mean <= 0) return mean;
    std::normal_distribution<double> normal(mean, d.spread);
    return std::clamp(normal(rng), mean / 3, mean * 3);
}

std::optional<TtffModel> TtffModel::parse(std::string_view spec, std::string &why) {
    TtffModel m;
    if (spec.empty()) {
        why = "expected KIND=MEAN[:SPREAD],... (kinds: cold, warm, hot, power)";
        return std::nullopt;
    }
    while (!spec.empty()) {
        const auto comma = spec.find(',');
        const std::string_view item = spec.substr(0, comma);
        spec = comma == std::string_view::npos ? std::string_view() : spec.substr(comma + 1);
        const auto eq = item.find('=');
        const std::string_view kind = item.substr(0, eq);
        Dist *d = kind == "cold"    ? &m.cold
                  : kind == "warm"  ? &m.warm
                  : kind == "hot"   ? &m.hot
                  : kind == "power" ? &m.power
                                    : nullptr;
        if (!d || eq == std::string_view::npos) {
            why = "expected KIND=MEAN[:SPREAD] with KIND cold, warm, hot or power, got '" +
                  std::string(item) + "'";
            return std::nullopt;
        }
        std::string_view value = item.substr(eq + 1), spread;
        if (const auto colon = value.find(':'); colon != std::string_view::npos) {
            spread = value.substr(colon + 1);
            value = value.substr(0, colon);
        }
        if (!number(value, d->mean) || d->mean < 0 || d->mean > 3600 ||
            (!spread.empty() &&
             (!number(spread, d->spread) || d->spread < 0 || d->spread > d->mean))) {
            why = std::string(kind) + ": expected MEAN[:SPREAD] seconds (mean 0..3600, spread " +
                  "0..mean), got '" + std::string(item.substr(eq + 1)) + "'";
            return std::nullopt;
        }
    }
    return m;
}

} // namespace gnss::sim
