#pragma once
// A force a wall's surface exerts on the fluid in front of it (the tunable-slip friction layer), over
// any shape that gives a distance and a normal. Wall adds it after the pair forces.
#include "core/Box.hpp"
#include "walls/WallShape.hpp"
#include "walls/WallStep.hpp"

#include <array>
#include <string>

namespace dpd {

class SurfaceForce {
public:
    virtual ~SurfaceForce() = default;

    // The keyword that names the force in the wall's entry (messages), and its part of the log's
    // account of the wall.
    virtual std::string keyword() const = 0;
    virtual std::string description() const = 0;
    // Why the force cannot act in this box (empty when it can), checked when a run is built.
    virtual std::string unfitFor(const Box&) const { return {}; }
    // Marks the axes along which the force makes the mean flow vary.
    virtual void markFlowAxes(const Box&, std::array<bool, 3>&) const {}
    // How far in front of the surface a builder starts the fluid: nearer, a repulsion that diverges at
    // the surface would throw a particle across the box on the first step.
    virtual double fluidStartsBeyond() const { return 0.0; }
    // Adds the force to the mobile particles in front of the surface; wallVelocity: the wall's.
    virtual void addForces(WallStep& s, const WallShape& shape, const Eigen::Vector3d& wallVelocity) const = 0;
};

}  // namespace dpd
