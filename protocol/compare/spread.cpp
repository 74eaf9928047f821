#include "compare/spread.h"

#include <algorithm>
#include <numeric>

namespace gnss::compare {

double quantile(const std::vector<double> &sorted, double q) {
    if (sorted.empty()) return 0;
    const double rank = q * static_cast<double>(sorted.size() - 1);
    const auto lo = static_cast<std::size_t>(rank);
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (sorted[hi] - sorted[lo]) * (rank - static_cast<double>(lo));
}

Spread spreadOf(std::vector<double> &values) {
    Spread s;
    s.count = values.size();
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(s.count);
    s.median = quantile(values, 0.5);
    s.p95 = quantile(values, 0.95);
    s.min = values.front();
    s.max = values.back();
    return s;
}

} // namespace gnss::compare
