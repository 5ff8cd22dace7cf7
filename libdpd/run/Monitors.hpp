#pragma once
// Cheap checks a run makes as it goes (METHODS.md section 2): kinetic temperature about the local
// flow, total momentum, particles behind walls, and non-finite numbers.
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dpd {

class System;

struct MonitorReport {
    double kT = 0.0;                     // kinetic temperature of the mobile particles about the local flow
    Eigen::Vector3d momentum{0, 0, 0};   // total momentum of the mobile particles
    Eigen::Vector3d meanVelocity{0, 0, 0};
    std::size_t mobile = 0;
    long insideWalls = 0;
    bool finite = true;                  // no NaN or infinity in positions, velocities or forces
};

// The local flow is a straight-line fit of the velocity against the coordinate in slabs of about one
// cutoff across `flowAxis` (the wall normal, or the gradient axis of a reverse-Poiseuille force);
// with flowAxis < 0 it is the global mean. A slab mean alone would count the shear inside the slab
// as heat: (shear x width)^2 / 12 per component, 0.17 kT at the walls of the published Poiseuille
// scene (shear rate 1.45, slabs of one cutoff). The fit leaves only the curvature's share, of order
// (g width^2 / nu)^2 / 720, below 1e-4 kT there. The temperature counts dimension x (N - 2 x number of
// slabs) degrees of freedom, since each slab's fit takes away two per dimension.
MonitorReport monitor(const System& sys, int flowAxis);

}  // namespace dpd
