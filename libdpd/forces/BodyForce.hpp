#pragma once
// External force per unit mass on every mobile particle: none, uniform (Poiseuille driving), or
// reverse Poiseuille (+g in the lower half of the box along `gradientAxis`, -g in the upper half;
// docs/analysis.md section 5: viscosity without walls).
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

struct BodyForce {
    enum class Type { none, uniform, reversePoiseuille };
    Type type = Type::none;
    Eigen::Vector3d g{0, 0, 0};
    int gradientAxis = 2;  // reverse Poiseuille only

    bool active() const { return type != Type::none && g.squaredNorm() > 0.0; }
    // Adds the body force to the forces of mobile particles.
    void apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box) const;
    // The force per unit mass at a point (for momentum bookkeeping and diagnostics).
    Eigen::Vector3d at(double coordinateAlongGradient, const Box& box) const;
};

BodyForce::Type bodyForceTypeFromName(const std::string& name);  // throws std::invalid_argument

}  // namespace dpd
