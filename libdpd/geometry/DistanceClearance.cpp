#include "geometry/DistanceClearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpd {

namespace {

// Entry i becomes the least of the entries i - below .. i + above along the axis (periodic).
void minimumAlongAxis(std::vector<float>& values, const BackgroundGrid& g, int axis, int below, int above) {
    const int n = g.n[axis];
    if (n == 1) return;
    const std::vector<float> in = values;
    if (below + above + 1 > n) below = above = n;  // the window covers the axis: every entry counts
    std::array<int, 3> c{};
    for (c[2] = 0; c[2] < g.n[2]; ++c[2])
        for (c[1] = 0; c[1] < g.n[1]; ++c[1])
            for (c[0] = 0; c[0] < g.n[0]; ++c[0]) {
                float least = std::numeric_limits<float>::infinity();
                std::array<int, 3> other = c;
                for (int k = -below; k <= above; ++k) {
                    other[axis] = BackgroundGrid::wrapIndex(c[axis] + k, n);
                    least = std::min(least, in[g.index(other[0], other[1], other[2])]);
                }
                values[g.index(c[0], c[1], c[2])] = least;
            }
}

}  // namespace

DistanceClearance::DistanceClearance(const SignedDistanceField& field, double span)
    : grid_(field.grid()), inverseSpacing_(grid_.spacing.cwiseInverse()), band_(field.band()),
      quantum_(field.band() / 254.0) {
    std::vector<float> least(grid_.size());
    for (std::size_t c = 0; c < least.size(); ++c) least[c] = field.tabulatedDistance(c);
    for (int a = 0; a < 3; ++a) {
        if (grid_.n[a] == 1) {
            span_[a] = std::numeric_limits<double>::infinity();
            continue;
        }
        const int m = std::max(1, static_cast<int>(std::ceil(span / grid_.spacing[a])));
        span_[a] = m * grid_.spacing[a] * (1.0 - 1e-9);
        minimumAlongAxis(least, grid_, a, m, m + 1);
    }
    // Rounded down, and a part in 10^6 further, so that steps x quantum never exceeds the least.
    clearance_.resize(least.size());
    for (std::size_t c = 0; c < least.size(); ++c) {
        const double steps = std::floor(least[c] / quantum_ * (1.0 - 1e-6));
        clearance_[c] = static_cast<std::uint8_t>(std::clamp(steps, 0.0, 255.0));
    }
}

}  // namespace dpd
