#pragma once
// Test scenes with polymer chains: the standard fluid with chains put in by the chain builder, every
// pair (fluid and beads alike) with the fluid's coefficients, FENE springs H 6, rMax 3.
#include "forces/FeneBond.hpp"
#include "setup/ChainBuilder.hpp"
#include "setup/StandardFluid.hpp"

#include <limits>
#include <memory>

namespace dpd::test {

inline Snapshot snapshotOf(const System& sys) {
    Snapshot s;
    s.box = sys.box;
    s.particles = sys.particles;
    s.speciesNames = sys.species.names();
    for (int k = 0; k < sys.species.size(); ++k) s.speciesFrozen.push_back(sys.species[k].frozen);
    s.bonds = sys.bonds.bonds();
    return s;
}

struct ChainScene {
    StandardFluidSettings fluid;
    long chains = 10;
    long length = 10;
    std::uint64_t chainSeed = 5;
    BondedPairs bondedPairs;
};

inline System makeChainedFluid(const ChainScene& scene) {
    const System fluid = makeStandardFluid(scene.fluid);
    Snapshot s = snapshotOf(fluid);
    const auto fene = std::make_shared<FeneBond>(6.0, 3.0);
    ChainSettings chains;
    chains.chains = scene.chains;
    chains.length = scene.length;
    chains.beadSpecies = "polymer";
    chains.fluidSpecies = "fluid";
    chains.clearance = 0.0;
    chains.seed = scene.chainSeed;
    chains.kT = scene.fluid.kT;
    insertChains(s, chains, *fene, [](const Eigen::Vector3d&) { return std::numeric_limits<double>::infinity(); });
    System sys;
    sys.box = s.box;
    sys.particles = s.particles;
    sys.species.add({"fluid", false});
    sys.species.add({"polymer", false});
    sys.pairs = PairTable(2);
    for (int a = 0; a < 2; ++a)
        for (int b = a; b < 2; ++b) sys.pairs.set(a, b, {scene.fluid.a, scene.fluid.gamma, 0.0, true});
    sys.forceParameters = {scene.fluid.cutoff, 2.0, scene.fluid.kT, scene.fluid.dt};
    sys.seed = scene.fluid.seed;
    sys.bonds = ChainBonds(s.bonds);
    sys.bondPotential = fene;
    sys.bondedPairs = scene.bondedPairs;
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

}  // namespace dpd::test
