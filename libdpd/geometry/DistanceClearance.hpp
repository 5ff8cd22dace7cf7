#pragma once
// How far from the solid surface every point near a point lies, at least. The field interpolates
// between the table entries at cell centres i0 and i0 + 1 along each axis (i0 = floor(u), u the
// position in cells less a half); for each i0 this holds the least entry from i0 - m to i0 + m + 1,
// where m cells make up span(). Every point within span() of a point along each axis interpolates
// between entries among those, and linear interpolation never goes below the least entry it weighs:
// the field's distance there is at least clearanceAt(point). A pass over particles reads this one
// number to learn that a particle, and every point of a short step it made, lie further from the
// surface than a wall acts, and looks no closer at it (docs/walls.md 3.2 step 6). The bound is kept
// in steps of 1/254 of the field's band, rounded down, a byte a cell (no step: the band's lower end):
// the table of a porous box stays in the core's cache while the particles are read past it.
#include "geometry/SignedDistanceField.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dpd {

class DistanceClearance {
public:
    // span: the displacement along each axis the bound must cover (a particle's usual step), rounded
    // up to whole cells m and then shortened by a part in 10^9, more than the rounding of a position
    // can move it across a cell edge.
    DistanceClearance(const SignedDistanceField& field, double span);

    // A lower bound of the field's distance at every point within span() of r along every axis.
    double clearanceAt(const Eigen::Vector3d& r) const {
        const std::uint8_t steps = clearance_[grid_.index(lowerEntry(r, 0), lowerEntry(r, 1), lowerEntry(r, 2))];
        return steps > 0 ? quantum_ * steps : -band_;
    }
    // Per axis: the displacement covered (infinite along an axis the field does not vary along).
    const Eigen::Vector3d& span() const { return span_; }

private:
    // i0 along the axis, wrapped into the grid.
    int lowerEntry(const Eigen::Vector3d& r, int axis) const {
        const int n = grid_.n[axis];
        if (n == 1) return 0;
        return BackgroundGrid::wrapIndex(
            static_cast<int>(std::floor((r[axis] - grid_.lo[axis]) * inverseSpacing_[axis] - 0.5)), n);
    }

    BackgroundGrid grid_;
    Eigen::Vector3d inverseSpacing_;
    Eigen::Vector3d span_;
    double band_;                           // the field's distances lie within +-band
    double quantum_;                        // the bound's step
    std::vector<std::uint8_t> clearance_;   // per grid cell, in steps; 0: no bound above -band
};

}  // namespace dpd
