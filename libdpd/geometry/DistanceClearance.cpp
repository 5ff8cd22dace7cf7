#include "geometry/DistanceClearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpd {

namespace {

// Entry i becomes the least of entries i and i + 1 along the axis (periodic).
void minimumWithNext(std::vector<float>& values, const BackgroundGrid& g, int axis) {
    const int n = g.n[axis];
    if (n == 1) return;
    const std::vector<float> in = values;
    std::array<int, 3> c{};
    for (c[2] = 0; c[2] < g.n[2]; ++c[2])
        for (c[1] = 0; c[1] < g.n[1]; ++c[1])
            for (c[0] = 0; c[0] < g.n[0]; ++c[0]) {
                std::array<int, 3> next = c;
                next[axis] = c[axis] + 1 == n ? 0 : c[axis] + 1;
                values[g.index(c[0], c[1], c[2])] =
                    std::min(in[g.index(c[0], c[1], c[2])], in[g.index(next[0], next[1], next[2])]);
            }
}

}  // namespace

DistanceClearance::DistanceClearance(const SignedDistanceField& field)
    : grid_(field.grid()), inverseSpacing_(grid_.spacing.cwiseInverse()), band_(field.band()),
      quantum_(field.band() / 254.0) {
    std::vector<float> least(grid_.size());
    for (std::size_t c = 0; c < least.size(); ++c) least[c] = field.tabulatedDistance(c);
    for (int a = 0; a < 3; ++a) {
        span_[a] = grid_.n[a] == 1 ? std::numeric_limits<double>::infinity() : 2.0 * grid_.spacing[a] * (1.0 - 1e-9);
        minimumWithNext(least, grid_, a);
    }
    clearance_ = inSteps(least);
    for (int a = 0; a < 3; ++a) minimumWithNext(least, grid_, a);  // entries i0 .. i0 + 2
    clearanceOfTwo_ = inSteps(least);
}

std::vector<std::uint8_t> DistanceClearance::inSteps(const std::vector<float>& least) const {
    // Rounded down, and a part in 10^6 further, so that steps x quantum never exceeds the least.
    std::vector<std::uint8_t> steps(least.size());
    for (std::size_t c = 0; c < least.size(); ++c)
        steps[c] = static_cast<std::uint8_t>(std::clamp(std::floor(least[c] / quantum_ * (1.0 - 1e-6)), 0.0, 255.0));
    return steps;
}

double DistanceClearance::leastOver(const int* first, const int* last) const {
    int count[3];  // entries along each axis, at most the whole axis
    for (int a = 0; a < 3; ++a) count[a] = std::min(last[a] - first[a] + 1, grid_.n[a]);
    std::uint8_t least = 255;
    for (int k = 0; k < count[2]; ++k)
        for (int j = 0; j < count[1]; ++j)
            for (int i = 0; i < count[0]; ++i)
                least = std::min(least, clearance_[grid_.index(BackgroundGrid::wrapIndex(first[0] + i, grid_.n[0]),
                                                               BackgroundGrid::wrapIndex(first[1] + j, grid_.n[1]),
                                                               BackgroundGrid::wrapIndex(first[2] + k, grid_.n[2]))]);
    return fromSteps(least);
}

}  // namespace dpd
