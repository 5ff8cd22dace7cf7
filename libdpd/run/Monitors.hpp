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

// The local flow is the mean velocity in slabs of about one cutoff across `flowAxis` (the wall
// normal, or the gradient axis of a reverse-Poiseuille force); with flowAxis < 0 it is the global
// mean. The temperature counts dimension x (N - number of slabs) degrees of freedom, since each
// slab's mean velocity takes away one per dimension.
MonitorReport monitor(const System& sys, int flowAxis);

}  // namespace dpd
