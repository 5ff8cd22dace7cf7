#pragma once
// The local mean flow that a run's temperature is measured about.
// The box is cut into cells across the axes along which the mean flow varies, and in each cell the
// velocity is fitted by a plane v = a + G (r - r_mean) (a straight line along one axis). A cell mean
// alone would count the shear inside the cell as heat, (shear x width)^2 / 12 per component; the
// fit leaves only the curvature's share, below 1e-4 kT in the published channels.
#include "core/Box.hpp"

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace dpd {

class System;

// The axes along which the mean flow may vary; none: the flow is one velocity (a periodic box).
struct FlowAxes {
    std::array<bool, 3> varies{false, false, false};

    int count() const { return int(varies[0]) + int(varies[1]) + int(varies[2]); }
    static FlowAxes none() { return FlowAxes{}; }
    // Along one axis; none for axis < 0.
    static FlowAxes along(int axis);
};

// Where a System's flow can vary: across each planar wall, along each axis a geometry wall varies
// on (in 2-D never y), and along a reverse-Poiseuille force's gradient axis.
FlowAxes flowAxesOf(const System& sys);

// Cells over the varying axes, the whole box along the others: about one cutoff wide along a
// single axis (slabs); with several axes wide enough to hold kParticlesPerCell mobile particles
// on average (and never under one cutoff), so that a plane's 4 parameters leave most of a cell's
// degrees of freedom as heat.
class LocalFlowCells {
public:
    static constexpr double kParticlesPerCell = 32.0;

    LocalFlowCells(const Box& box, const FlowAxes& axes, double cutoff, std::size_t mobile);

    std::size_t count() const { return count_; }
    std::size_t cellOf(const Eigen::Vector3d& r) const;
    // Position relative to the cell's centre along the varying axes, zero along the others.
    Eigen::Vector3d offsetInCell(const Eigen::Vector3d& r, std::size_t cell) const;

private:
    int indexAlong(int axis, double coordinate) const;

    Box box_;
    FlowAxes axes_;
    std::array<int, 3> n_{1, 1, 1};
    Eigen::Vector3d width_{0, 0, 0};
    std::size_t count_ = 1;
};

// Sums of one cell for the least-squares plane of each velocity component.
struct LocalFlowSums {
    long n = 0;
    Eigen::Vector3d s{0, 0, 0};     // sum of offsets
    Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
    Eigen::Vector3d v{0, 0, 0};     // sum of velocities
    Eigen::Vector3d vv{0, 0, 0};    // sum of squared velocity components
    Eigen::Matrix3d vs = Eigen::Matrix3d::Zero();  // (component, axis): sum of v_c s_a

    void add(const Eigen::Vector3d& offset, const Eigen::Vector3d& velocity);

    struct Residual {
        Eigen::Vector3d squares{0, 0, 0};  // per component, about the fitted plane
        int parameters = 1;                // fitted per component: 1 + the rank of the offsets' spread
    };
    // About the plane over the directions the cell's offsets span (the mean alone when they span none).
    Residual residual() const;
};

}  // namespace dpd
