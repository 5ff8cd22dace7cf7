#include "setup/ChainedFluid.hpp"

#include "forces/FeneBond.hpp"
#include "setup/ChainBuilder.hpp"

#include <limits>

namespace dpd {

namespace {

Snapshot snapshotOf(const System& sys) {
    Snapshot s;
    s.box = sys.box;
    s.particles = sys.particles;
    s.speciesNames = sys.species.names();
    for (int k = 0; k < sys.species.size(); ++k) s.speciesFrozen.push_back(sys.species[k].frozen);
    return s;
}

}  // namespace

System makeChainedFluid(const ChainedFluidSettings& settings) {
    StandardFluidSettings whole = settings.fluid;
    whole.ranks = nullptr;  // chains are put in the whole box; initialise keeps each rank's slab of it
    const System fluid = makeStandardFluid(whole);
    Snapshot s = snapshotOf(fluid);
    const auto fene = std::make_shared<FeneBond>(6.0, 3.0);
    ChainSettings chains;
    chains.chains = settings.chains;
    chains.length = settings.length;
    chains.beadSpecies = "polymer";
    chains.fluidSpecies = "fluid";
    chains.clearance = 0.0;
    chains.seed = settings.chainSeed;
    chains.kT = settings.fluid.kT;
    insertChains(s, chains, *fene, [](const Eigen::Vector3d&) { return std::numeric_limits<double>::infinity(); });
    System sys;
    sys.box = s.box;
    sys.particles = s.particles;
    sys.species.add({"fluid", false});
    sys.species.add({"polymer", false});
    sys.pairs = PairTable(2);
    for (int a = 0; a < 2; ++a)
        for (int b = a; b < 2; ++b) sys.pairs.set(a, b, {settings.fluid.a, settings.fluid.gamma, 0.0, true});
    sys.forceParameters = {settings.fluid.cutoff, 2.0, settings.fluid.kT, settings.fluid.dt};
    sys.seed = settings.fluid.seed;
    sys.bonds = ChainBonds(s.bonds);
    sys.bondPotential = fene;
    sys.bondedPairs = settings.bondedPairs;
    sys.ranks = settings.fluid.ranks;
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    return sys;
}

}  // namespace dpd
