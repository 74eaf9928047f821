#pragma once
// Spread: mean, median and 95th percentile of a set of values (differences in metres or dB).
#include <cstddef>
#include <vector>

namespace gnss::compare {

struct Spread {
    std::size_t count = 0;
    double mean = 0, median = 0, p95 = 0, min = 0, max = 0;
};

// The q-quantile (0..1) of `sorted` by linear interpolation between ranks; 0 when empty.
double quantile(const std::vector<double> &sorted, double q);
// The spread of `values` (sorted in place).
Spread spreadOf(std::vector<double> &values);

} // namespace gnss::compare
