#pragma once
// How far from the solid surface every point of a short path lies, at least. The field interpolates
// between the table entries at cell centres i0 and i0 + 1 along each axis (i0 = floor(u), u the
// position in cells less a half), and linear interpolation never goes below the least entry it
// weighs; this table holds, for each i0, the least of the entries i0 and i0 + 1 along every varying
// axis. The points of a straight path interpolate between entries of the i0 its ends span, so the
// least of a few table values bounds the field's distance along all of it. A second table holds the
// least over i0 and i0 + 1 a varying axis, so that a path whose ends differ by one i0 along some axes
// (about half of a step's paths on a grid of 1/8 cutoff) also reads one byte. A pass
// over particles reads these to learn that a particle, and every point of the step it made, lie
// further from the surface than a wall acts, and looks no closer at it (docs/walls.md 3.2 step 6).
// The bound is kept in steps of 1/254 of the field's band, rounded down, a byte a cell (no step: the
// band's lower end): the table of a porous box stays in the core's cache while the particles are
// read past it.
#include "geometry/SignedDistanceField.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace dpd {

class DistanceClearance {
public:
    explicit DistanceClearance(const SignedDistanceField& field);

    // A lower bound of the field's distance at every point of the straight path from `from` to `to`,
    // which must lie within span() of each other along every axis.
    double clearanceAlong(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
        int first[3], last[3];
        for (int a = 0; a < 3; ++a) entryRange(from[a], to[a], a, first[a], last[a]);
        const std::size_t cell = grid_.index(BackgroundGrid::wrapIndex(first[0], grid_.n[0]),
                                             BackgroundGrid::wrapIndex(first[1], grid_.n[1]),
                                             BackgroundGrid::wrapIndex(first[2], grid_.n[2]));
        if (first[0] == last[0] && first[1] == last[1] && first[2] == last[2]) return fromSteps(clearance_[cell]);
        if (last[0] - first[0] <= 1 && last[1] - first[1] <= 1 && last[2] - first[2] <= 1)  // most of the rest
            return fromSteps(clearanceOfTwo_[cell]);
        return leastOver(first, last);
    }
    // Per axis: the longest path covered, two grid cells shortened by a part in 10^9 (infinite along
    // an axis the field does not vary along).
    const Eigen::Vector3d& span() const { return span_; }

private:
    // The range of i0 along the axis that the path's points may interpolate from, widened by a part
    // in 10^9 of a cell each way (more than rounding moves a position across a cell edge), not yet
    // wrapped into the grid.
    void entryRange(double from, double to, int axis, int& first, int& last) const {
        if (grid_.n[axis] == 1) {
            first = last = 0;
            return;
        }
        const double u = (from - grid_.lo[axis]) * inverseSpacing_[axis] - 0.5;
        const double w = (to - grid_.lo[axis]) * inverseSpacing_[axis] - 0.5;
        first = static_cast<int>(std::floor(std::min(u, w) - 1e-9));
        last = static_cast<int>(std::floor(std::max(u, w) + 1e-9));
    }
    std::vector<std::uint8_t> inSteps(const std::vector<float>& least) const;
    double fromSteps(std::uint8_t steps) const { return steps > 0 ? quantum_ * steps : -band_; }
    // The least table value over i0 from first to last along each axis (wrapped periodically).
    double leastOver(const int* first, const int* last) const;

    BackgroundGrid grid_;
    Eigen::Vector3d inverseSpacing_;
    Eigen::Vector3d span_;
    double band_;                           // the field's distances lie within +-band
    double quantum_;                        // the bound's step
    std::vector<std::uint8_t> clearance_;   // per grid cell, in steps; 0: no bound above -band
    std::vector<std::uint8_t> clearanceOfTwo_;  // the same over i0 and i0 + 1 a varying axis
};

}  // namespace dpd
