#include "BenchmarkScenes.hpp"

#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"
#include "setup/ChainedFluid.hpp"
#include "setup/StandardFluid.hpp"
#include "setup/BlockFrozenWall.hpp"

#include <cmath>
#include <sstream>

namespace dpd {

BenchmarkScene makeFluidScene(std::size_t particles, double a, int dimension, const Communicator& ranks) {
    StandardFluidSettings fluid;
    fluid.particles = particles * static_cast<std::size_t>(ranks.size());
    fluid.aspect.x() = ranks.size();
    fluid.ranks = &ranks;
    fluid.a = a;
    fluid.dimension = dimension;
    return {"fluid", makeStandardFluid(fluid), FunctionObjects(), -1};
}

BenchmarkScene makeChainsScene(std::size_t particles, double a, const Communicator& ranks) {
    ChainedFluidSettings s;
    s.fluid.particles = particles * static_cast<std::size_t>(ranks.size());
    s.fluid.aspect.x() = ranks.size();
    s.fluid.ranks = &ranks;
    s.fluid.a = a;
    s.length = 30;
    s.chains = std::max<long>(1, static_cast<long>(s.fluid.particles / 10 / 30));  // 10 % of the particles
    return {"chains", makeChainedFluid(s), FunctionObjects(), -1};
}

namespace {

// constant/dpdProperties of tutorials/channel/poiseuille with the walls at z = -10 and 10.
const char* const kChannelProperties = R"(
dimension 3; kT 1; cutoff 1; seed 2026;
species { fluid { frozen no; } wall { frozen yes; } }
pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }
integrator { type GrootWarren; lambda 0.65; }
bodyForce { type uniform; value (0.02 0 0); }
walls
{
    lower { type plane; point (0 0 -10); normal (0 0 1); velocity (0 0 0); reflection bounceBack; }
    upper { type plane; point (0 0 10); normal (0 0 -1); velocity (0 0 0); reflection bounceBack; }
}
)";

}  // namespace

BenchmarkScene makeChannelScene(std::size_t particles) {
    const Dictionary properties = Dictionary::parse(kChannelProperties, "dpdBenchmark channel dpdProperties");
    const DpdModel model = readDpdModel(properties);
    // 22 cutoffs across z (20 of fluid, a wall cutoff each side) at density 4: N = 88 L^2.
    const double side = std::sqrt(static_cast<double>(particles) / 88.0);
    std::ostringstream wall;
    wall << "box { min (" << -side / 2 << " " << -side / 2 << " -11); max (" << side / 2 << " " << side / 2
         << " 11); }\nfluid { species fluid; density 4; }\nwall { species wall; lattice fcc; density 4; thickness 1; }\n";
    BlockFrozenWallReport report;
    Snapshot snapshot =
        buildBlockFrozenWall(Dictionary::parse(wall.str(), "dpdBenchmark channel blockFrozenWallDict"), model, report);
    BenchmarkScene scene{"channel", buildSystem(model, std::move(snapshot), 0.04, "dpdBenchmark channel"),
                         FunctionObjects(), 2};
    const Dictionary functions = Dictionary::parse(
        "profile { type binnedProfile; axis z; nBins 44; min -11; max 11; samplesPerBlock 100; }",
        "dpdBenchmark channel functions");
    scene.sampling = FunctionObjects::read(functions, scene.system);
    scene.system.sortByCell();
    scene.system.computeForces();
    return scene;
}

}  // namespace dpd
