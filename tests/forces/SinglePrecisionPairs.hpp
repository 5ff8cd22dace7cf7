#pragma once
// How far the pair loop's single-precision separations (forces/PairInputs.hpp) may be from the exact
// ones, and what that can do to a pair's force: the tolerances of the tests that compare the loop with
// a double-precision reference.
//
// A component of r_i - r_j is built from two cell-local coordinates (|x| <= h, the cell size, each
// rounded to float: at most u 2h apiece, u = 2^-24 the unit round-off), the candidate's offset (the
// cell size rounded, times a stencil offset of at most 2, then added with one rounding: u 4h + u 4h),
// the offset added to the coordinate (|.| <= 3h: u 6h) and the subtraction (|.| <= 4h: u 8h). In all
// at most 26 u h per component, about 1.5e-6 h; the squared distance then differs by at most
// 2 sqrt(3) (26 u h) r plus its own three roundings (u 4 r^2 each at most).
#include "core/Species.hpp"

#include <Eigen/Core>

#include <cmath>

namespace dpd::test {

inline constexpr double kUnitRoundoff = 0x1p-24;

inline double separationComponentError(double cellSize) { return 26.0 * kUnitRoundoff * cellSize; }

inline double squaredDistanceError(double cellSize, double r) {
    return 2.0 * std::sqrt(3.0) * separationComponentError(cellSize) * r + 12.0 * kUnitRoundoff * r * r;
}

// The most the force s(d) d of one pair can change, per component, when every component of its
// separation d moves by up to `delta` (with r.v following the separation, plus its own float rounding
// of at most 4u |d| |dv|): the first-order change summed over the three axes, each measured by moving
// the separation by delta along that axis. Twice that, for the second-order terms.
template <class Evaluator>
double pairForceError(const Evaluator& eval, const Eigen::Vector3d& d, const Eigen::Vector3d& dv, const PairCoeffs& c,
                      double zeta, double delta) {
    const auto force = [&](const Eigen::Vector3d& s, double rDotVShift) {
        return (eval.forceOverR(s.squaredNorm(), s.dot(dv) + rDotVShift, c, zeta) * s).eval();
    };
    const Eigen::Vector3d f = force(d, 0.0);
    double bound = (force(d, 4.0 * kUnitRoundoff * d.norm() * dv.norm()) - f).cwiseAbs().maxCoeff();
    for (int a = 0; a < 3; ++a) {
        Eigen::Vector3d moved = d;
        moved[a] += delta;
        bound += (force(moved, 0.0) - f).cwiseAbs().maxCoeff();
    }
    return 2.0 * bound;
}

}  // namespace dpd::test
