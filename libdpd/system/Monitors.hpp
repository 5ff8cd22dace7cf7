#pragma once
// Cheap checks a run makes as it goes (docs/methods.md section 2): kinetic temperature about the local
// flow, total momentum, particles behind walls, and non-finite numbers.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "system/LocalFlowFit.hpp"

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

// kT about the local flow (system/LocalFlowFit.hpp): a plane fitted in cells across `flow`'s axes (none:
// the global mean). It counts dimension x (N - parameters) degrees of freedom per cell, since each
// cell's fit takes that many away per velocity component.
MonitorReport monitor(const System& sys, const FlowAxes& flow);
// The same across one axis (slabs of about one cutoff); flowAxis < 0: about the global mean.
MonitorReport monitor(const System& sys, int flowAxis);

}  // namespace dpd
