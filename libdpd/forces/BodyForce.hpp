#pragma once
// An external force per unit mass on every mobile particle. Types are chosen by name in the bodyForce
// block of constant/dpdProperties (forces/BodyForceTypes.cpp: none, uniform, reversePoiseuille), each
// reading its own coefficients.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "core/Registry.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;

class BodyForce {
public:
    virtual ~BodyForce() = default;
    virtual std::string typeName() const = 0;
    // g: the force per unit mass (for a force that changes sign across the box, its value where it is +g).
    virtual Eigen::Vector3d value() const = 0;
    // The axis along which the force changes, -1 where it is the same everywhere.
    virtual int gradientAxis() const { return -1; }
    bool uniform() const { return gradientAxis() < 0; }
    bool active() const { return value().squaredNorm() > 0.0; }
    // Adds the force to the forces of the mobile particles.
    virtual void apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box) const = 0;
};

// The body force of a scene without one.
std::shared_ptr<const BodyForce> noBodyForce();

// The bodyForce block's `value`: a vector, with no y component in a 2-D scene.
Eigen::Vector3d readBodyForceValue(const Dictionary& d, int dimension);

using BodyForceRegistry = Registry<BodyForce, const Dictionary&, int /*dimension*/>;
const BodyForceRegistry& bodyForceRegistry();

// The bodyForce block of constant/dpdProperties (none when there is none); errors name its keywords.
std::shared_ptr<const BodyForce> readBodyForce(const Dictionary& dpdProperties, int dimension);

}  // namespace dpd
