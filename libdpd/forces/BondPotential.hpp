#pragma once
// The spring between bonded particles (polymer chains, docs/methods.md section 4). Types are chosen by
// name in the bonds block of constant/dpdProperties (forces/BondPotentialTypes.cpp: FENE), each reading
// its own coefficients and running the bond pass with its own small evaluator (forces/BondForceLoop.hpp).
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace dpd {

class Dictionary;
class ChainBonds;
struct Particles;
struct Box;
struct BondPassResult;

class BondPotential {
public:
    virtual ~BondPotential() = default;
    virtual std::string typeName() const = 0;
    virtual std::string description() const = 0;  // for the log
    // Bonds at or beyond this length have no force: a run that finds one stops (forces/ChainBonds.hpp).
    virtual double maxLength() const = 0;
    virtual double energy(double r) const = 0;
    // The force on the second particle along the bond vector b = r_second - r_first, divided by r:
    // F_second = forceOverR(r^2) b, F_first = -F_second.
    virtual double forceOverR(double r2) const = 0;
    // Adds every bond's force (the pass, without a virtual call per bond).
    virtual BondPassResult addForces(ChainBonds& bonds, Particles& p, const Box& box) const = 0;
};

using BondPotentialRegistry = Registry<BondPotential, const Dictionary&>;
const BondPotentialRegistry& bondPotentialRegistry();

}  // namespace dpd

namespace dpd {

// The bonds block of constant/dpdProperties (null when there is none); errors name its keywords.
std::shared_ptr<const BondPotential> readBondPotential(const Dictionary& dpdProperties);

}  // namespace dpd
