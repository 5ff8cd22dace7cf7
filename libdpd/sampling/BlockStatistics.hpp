#pragma once
// Statistics of block averages: one block much longer than the correlation time is one independent
// measurement, so the spread of block means gives an honest standard error for correlated data.
#include <cmath>
#include <vector>

namespace dpd {

// Standard error of the mean of the values (0 for fewer than two).
inline double standardErrorOfMean(const std::vector<double>& values) {
    const std::size_t m = values.size();
    if (m < 2) return 0.0;
    double mean = 0.0;
    for (double v : values) mean += v;
    mean /= static_cast<double>(m);
    double var = 0.0;
    for (double v : values) var += (v - mean) * (v - mean);
    return std::sqrt(var / static_cast<double>(m - 1) / static_cast<double>(m));
}

}  // namespace dpd
